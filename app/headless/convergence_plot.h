// The plot of a convergence study (`sph converge`'s converge.png): log10 of the error against log10 of
// the step (dx or dt), drawn on the plane view as outlines: the runs as dots, the least-squares line, and
// order-1 and order-2 guide lines through the coarsest run, each with its legend row. No particle field,
// so no colour bar (the old 1D profile's bar repeated the vertical axis).
#pragma once
#include "sph/convergence.h"
#include "sph/snapshot.h"

namespace sph::cli {

Snapshot convergence_plot(const ConvergenceResult& r);

}  // namespace sph::cli

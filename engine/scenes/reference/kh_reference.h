// The Kelvin-Helmholtz scene's reference: the amplitude of the seeded mode (McNally, Lyra & Passy 2012,
// ApJS 201, 18, their mode-amplitude diagnostic: the projection of v_y on sin and cos(4 pi x), weighted by
// exp(-4 pi |y - y_interface|), with the cell area replaced by the particle volume m/rho), its exponential
// growth rate fitted over a window of the linear phase, and the linear theory's rate of the same smooth,
// compressible profile (kh_linear.h).
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// ramp: the layer width L; gamma: the gas's; the rate is fitted to ln(amplitude) at the evaluations with
/// t in [fit_t0, fit_t1] seen so far (the reference keeps that history; a time earlier than the last
/// one, a reset, clears it).
std::unique_ptr<Reference> make_kh_reference(double ramp, double gamma, double fit_t0, double fit_t1);

/// The linear growth rate of the scene's profile at k = 4 pi [1/time].
double kh_theory_rate(double ramp, double gamma);

/// The mode amplitude of the particles (McNally et al.'s diagnostic with V = m/rho).
double kh_mode_amplitude(const Particles& p);

}  // namespace sph::scenes

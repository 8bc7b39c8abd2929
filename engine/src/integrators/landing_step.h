// The step towards a target time (an output, a probe, t_end, run A's time for run B) that lands on it
// without a sliver: a step and a sliver of one become two equal steps, so no step is shorter than half
// the free one. A sliver was more than a small step: DFSPH's pressure holds the divergence solve's, which
// scales as 1/dt, and the hydrostatic tank's mid-depth pressure came out 3.6% low at t = 0.7 s, where a
// step of a quarter of the free one landed on the output; with two equal steps it is within 1.4% at every
// output (1.1% low on average with M4 at h = 1.3 dx: its gradient sum on the lattice, engine/scenes/dfsph_liquids.cpp).
#pragma once

namespace sph {

/// The step [time] at most `dt_free` (the stages' step) that reaches a target `remaining` ahead in one
/// step or in two equal ones. A remaining time within rounding of dt_free is taken whole: a run that
/// follows another one of the same dt (an A/B run B, a sweep's run) takes its steps, not two halves of
/// each (7.8e-4 in rho on Sod when the remaining time came out one rounding above its dt).
inline double landing_step(double dt_free, double remaining) {
  if (dt_free >= remaining * (1.0 - 1e-10)) return remaining;
  if (dt_free > 0.5 * remaining) return 0.5 * remaining;
  return dt_free;
}

}  // namespace sph

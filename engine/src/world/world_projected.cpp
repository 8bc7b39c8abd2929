// The step of a scene whose pressure is solved for (DFSPH, physics.eos = dfsph): the stage's project()
// sets the new velocities from the current state's other forces, then the particles move with them
// (symplectic Euler, Bender & Koschier 2017 Algorithm 1). The integrator (time.integrator) is not used.
#include "core/parallel.h"
#include "core/pipeline.h"
#include "core/stage.h"
#include "sph/world.h"

namespace sph {

void World::advance_projected(double dt_max) {
  const double dt = step_length(dt_max);
  if (!current_) evaluate(t_);
  prepare_neighbours();  // the lists of this state (kept from the evaluation), coordinates as they expect
  {
    StageContext ctx = context();
    pipeline_->projector()->project(ctx, dt);
  }
  lists_.rewrap(p_);
  const std::size_t n = p_.fluid();
  for (int k = 0; k < p_.dim(); ++k) {
    auto& x = p_.x[k];
    const auto& v = p_.v[k];
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) x[i] += dt * v[i];
  }
  current_ = false;  // the rates belong to the state before the step
  end_step(dt);
  checks_.check_projection(stats_->projection, cfg_.params.liquid, step_, t_);
}

}  // namespace sph

// The evaluation the inspector explains: the scene's stages run once more, on a copy of the particles,
// at the current state (positions, velocities and evolved fields as they are now), one stage at a time,
// recording what each stage adds to one particle's dv/dt and du/dt. The running World is not touched:
// the copy has its own ghosts, neighbour lists and freshly built stages, so inspecting a run never
// changes it.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/pipeline.h"
#include "core/stage.h"
#include "sph/vec.h"

namespace sph {

/// What one stage added to the inspected particle's rates.
struct StageDelta {
  std::string stage;
  bool sets = false;  ///< the stage sets the accelerations (the force stage): `a` is its whole result
  Vec3 a;             ///< [length/time^2]
  double dudt = 0.0;  ///< [length^2/time^3]
};

struct FreshEvaluation {
  Particles p;                  ///< the copy, evaluated (ghosts included)
  NeighbourList nl;             ///< its neighbour lists
  std::vector<double> h_limit;  ///< the largest h each list covers
  EvalStats stats;
  std::unique_ptr<Pipeline> pipeline;
  std::vector<StageDelta> deltas;  ///< per stage in pipeline order, for the inspected particle
};

/// What the evaluation needs from the World (the same values World::context() hands its stages).
struct FreshInputs {
  const Params& prm;
  const Kernel& kernel;
  const Domain& domain;
  double eta = 0.0, spacing = 0.0, wall_strength = 0.0;
};

/// Evaluates a copy of `state` (real particles; ghosts are rebuilt) and records the stage deltas of the
/// particle at storage index i. Throws std::runtime_error if h keeps outgrowing the lists.
FreshEvaluation evaluate_fresh(const FreshInputs& in, const Particles& state, std::size_t i);

/// The context the stages ran with, for term-by-term sums over the same lists.
StageContext fresh_context(const FreshInputs& in, FreshEvaluation& e);

}  // namespace sph

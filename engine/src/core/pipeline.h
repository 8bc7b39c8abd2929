// The stages of a scene's physics in pipeline order, and the fields they need between them.
#pragma once
#include <memory>
#include <vector>

#include "core/stage.h"

namespace sph {

class Pipeline {
 public:
  /// The stages of `prm.physics` (assumed valid: Physics::validate) for a scene of dimension dim; the
  /// softening adds the grad-h stages of kernel-softened gravity.
  Pipeline(const Params& prm, int dim);
  const std::vector<std::unique_ptr<Stage>>& stages() const { return stages_; }
  /// Every field a stage reads, writes or evolves, plus mass and h.
  FieldSet fields() const { return fields_; }
  /// The evolved state fields and their rates.
  const std::vector<EvolvedPair>& evolved() const { return evolved_; }
  /// Some stage sets the accelerations (otherwise the world zeroes them).
  bool sets_acceleration() const { return sets_a_; }
  /// Particles drift with v + an XSPH correction.
  bool drifts() const { return drifts_; }
  /// Some stage reads the neighbour lists.
  bool uses_neighbours() const { return uses_neighbours_; }
  /// Some stage reads every entry of its lists without testing the distance (Stage::exact_lists).
  bool exact_lists() const { return exact_lists_; }
  /// With individual time steps the lists may be gathered only for the particles an evaluation visits:
  /// no stage reads every list (Stage::reads_every_list) nor wants exact lists.
  bool lists_by_rows() const { return uses_neighbours_ && !exact_lists_ && !every_list_; }
  /// The stage that steps the scene by a pressure solve (Stage::projects), or null.
  Stage* projector() const { return projector_; }

 private:
  std::vector<std::unique_ptr<Stage>> stages_;
  FieldSet fields_;
  std::vector<EvolvedPair> evolved_;
  Stage* projector_ = nullptr;
  bool sets_a_ = false, drifts_ = false, uses_neighbours_ = false, exact_lists_ = false, every_list_ = false;
};

}  // namespace sph

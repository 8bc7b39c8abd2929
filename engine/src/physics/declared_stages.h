// Stages whose per-pair terms live inside the force loops (pair_terms.h) for speed: they declare what
// they allocate and evolve and their timestep limits, and run nothing themselves.
#pragma once
#include "core/stage.h"

namespace sph {

/// A stage that only declares fields (and optionally an evolved pair).
class DeclaredStage : public Stage {
 public:
  DeclaredStage(std::string_view name, FieldSet needs, std::vector<EvolvedPair> evolves = {})
      : Stage({.name = name, .needs = needs}), evolves_(std::move(evolves)) {}
  std::vector<EvolvedPair> evolves() const override { return evolves_; }
  bool reads_every_list() const override { return false; }  // runs nothing

 private:
  std::vector<EvolvedPair> evolves_;
};

}  // namespace sph

// `sph run A --compare B --compare-set key=value ...`: run B of an A/B comparison, stepped with run A to
// the same times and drawn with it in every frame (profiles: both runs' dots and the exact curve, each
// run's L1 error in the legend; 2D: A, B and the difference map; 3D: A and B).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/world.h"

namespace sph::cli {

struct CompareOptions {
  std::string scene;              ///< --compare: run B's scene name or JSON file ("" = run A's config)
  std::vector<std::string> sets;  ///< --compare-set key=value: applied to run B after its scene
};

struct CompareSetup {
  RunConfig b;
  std::vector<std::string> differences;  ///< key=value in which B differs from A (the labels show them)
  std::string label_a, label_b;          ///< "A: kernel.type=M4", "B: kernel.type=M6"
};

/// Run B's configuration, or nullopt without --compare and --compare-set. B must be the same scene
/// family as A (its exact curve is A's); --until applies to both. Throws ConfigError naming the flag.
std::optional<CompareSetup> resolve_compare(const CompareOptions& opt, const RunConfig& a, double until);

/// A line for the summary: "run B (kernel.type=M6): t = ..., L1_rho = ...".
std::string compare_summary(const World& b, const CompareSetup& setup);

/// (name, value) of every reference column of w now: what the frames' legends read their L1 from.
std::vector<std::pair<std::string, double>> reference_errors(const World& w);

}  // namespace sph::cli

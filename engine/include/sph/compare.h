// A/B comparisons: run B is run A's configuration with some parameters changed ("overrides", key=value
// as `--set` takes them: "kernel.type=M6", "visc.alpha=0", "scene.n_left=800"). Shared by the GUI's
// stepper and `sph run --compare`.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "sph/config.h"

namespace sph {

/// A's config with the overrides applied, validated; throws ConfigError naming the override.
RunConfig fork_config(const RunConfig& a, const std::vector<std::string>& overrides);

/// "kernel.type=M6, visc.alpha=0": the overridden keys with their values in `cfg` (A's values for run
/// A's label, B's for run B's); a key cfg does not know is left out.
std::string compare_label(const RunConfig& cfg, const std::vector<std::string>& overrides);

/// A sweep's values typed as text: split at commas, semicolons, spaces, tabs and newlines, empty items dropped.
std::vector<std::string> sweep_values(const std::string& text);

/// The most runs a parameter sweep adds to run A (the profiles have one run colour more).
inline constexpr std::size_t kMaxSweepRuns = 5;

/// "KEY=V1,V2,..." (as --sweep takes it): false (with *err saying what is wrong) without a key, an '=' or a
/// value, or with more than kMaxSweepRuns values.
bool split_sweep(const std::string& text, std::string* key, std::vector<std::string>* values, std::string* err);

/// The keys in which b differs from a: every run parameter of the param table (physics slots included)
/// and every scene value, as key=value with b's values, in table order.
std::vector<std::string> differences(const RunConfig& a, const RunConfig& b);

}  // namespace sph

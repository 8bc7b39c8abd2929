// `sph run SCENE --sweep KEY=V1,V2,...`: run A beside one more run per value of KEY (at most 5), each stepped
// to A's times and drawn with it in every frame (profiles: every run's dots in its own colour with its L1 in
// the legend, as the GUI's Sweep panel). The sweep's runs write no files of their own: the summary gives
// each one's reference values, a divergence names the run, and an energy beyond the scene's bound in any
// run is reported as for run A.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/world.h"

namespace sph::cli {

class SweepRuns {
 public:
  /// The sweep's configurations (A's with key=value each; --until applies to all), or nullptr for an empty
  /// `text`; ConfigError names --sweep and what is wrong.
  static std::unique_ptr<SweepRuns> resolve(const std::string& text, const RunConfig& a, double until);
  /// What is wrong with the form of `text` (not KEY=V1,V2, more than 5 values, or beside --compare), or "".
  static std::string usage_error(const std::string& text, bool comparing);

  /// Builds the runs' Worlds (DivergedError for a start that cannot be solved, as run A's).
  void build();
  /// Steps every run to t; `current` is the run being stepped while it steps (a divergence's culprit), and
  /// a divergence prints which run it was before it passes on.
  void advance_to(double t, const World*& current);
  /// World::check_output of every run (its energy at an output time).
  void check_output(const World*& current);
  const std::string& key() const { return key_; }
  std::size_t size() const { return worlds_.size(); }
  const World& world(std::size_t k) const { return *worlds_[k]; }
  const std::string& label(std::size_t k) const { return labels_[k]; }  ///< "kernel.eta=1.5"
  /// A summary line per run: "sweep run kernel.eta=1.5: t = ..., L1_rho = ...".
  void print_summary() const;
  void print_warnings() const;
  /// Whether a run's energy drifted beyond its scene's bound.
  bool energy_beyond_bound() const;

 private:
  std::string key_;
  std::vector<std::string> labels_;   // "kernel.eta=1.5"
  std::vector<RunConfig> configs_;
  std::vector<std::unique_ptr<World>> worlds_;
};

}  // namespace sph::cli

// What a World reports about its current state: conserved quantities, the reference's values, snapshots
// for viewers, the tree overlay, the particle inspector and what the evaluations cost. A read-only view
// over the world's parts (World::report()), for the moment it is taken: it changes nothing, and is valid
// while the world is neither stepped nor changed.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/density.h"
#include "sph/diagnostics.h"
#include "sph/inspect.h"
#include "sph/kernel.h"
#include "sph/push.h"
#include "sph/reference.h"
#include "sph/snapshot.h"

namespace sph {

class NeighbourCache;
class Pipeline;
struct EvalStats;
struct StageContext;

/// Wall time spent in one part of the evaluation since the world was built (or the pipeline changed):
/// "neighbours" (ghosts and lists), then each stage by name. For benchmarks and the GUI's cost view.
struct StageTiming {
  std::string name;
  double seconds = 0.0;
  std::int64_t calls = 0;
};

class Report {
 public:
  /// The world's parts a report reads.
  struct Inputs {
    const RunConfig& cfg;
    const Kernel& kernel;
    const Particles& p;
    const std::vector<std::uint32_t>& by_id;  ///< storage indices of the real particles in increasing id
    const Domain& domain;
    const Pipeline& pipeline;
    EvalStats& stats;  ///< the last evaluation's (the stages' energy sums take it mutable)
    const NeighbourCache& lists;
    const Reference* reference;
    const std::vector<RefColumn>& ref_columns;
    const std::vector<StageTiming>& timings;
    const Push& push;
    double eta, spacing, wall_strength;  ///< effective eta, the scene's particle spacing and wall D
    double since;                        ///< time between the last two evaluations (0 when unknown)
    double t, dt;                        ///< the time and the last step's dt
    std::int64_t step, evaluations;
    std::int64_t updates;  ///< particle evaluations so far (every fluid particle, or the active ones)
  };
  explicit Report(const Inputs& in) : in_(in) {}

  /// E_kin, E_int, E_pot, momentum, angular momentum and the h solve's figures now.
  Diagnostics diagnostics() const;
  bool has_reference() const { return in_.reference != nullptr; }
  const Reference* reference() const { return in_.reference; }
  /// The reference's columns and their values now (empty without a reference).
  const std::vector<RefColumn>& reference_columns() const { return in_.ref_columns; }
  std::vector<double> reference_values() const;
  /// One reference value by column name; throws std::out_of_range if there is no such column.
  double reference_value(const std::string& name) const;
  /// Copy of what a viewer needs (floats): positions, h, kinds, every display field, reference curves.
  Snapshot snapshot() const;
  /// The Barnes-Hut cells the walk of particle k (a snapshot index) takes now, at the current theta and
  /// guard (the tree overlay); empty when the scene's gravity is not the tree or k is out of range.
  std::vector<TreeCell> tree_cells(std::size_t k) const;
  /// Particle `id` taken apart (sph/inspect.h): its fields, neighbours and the terms of its equations,
  /// re-evaluated at the current state on a copy of the particles (the run itself is not changed; costs
  /// one evaluation). nullopt if there is no such particle.
  std::optional<Inspection> inspect(std::int64_t id) const;

  const DensityStats& density_stats() const;  ///< the last h solve's
  std::int64_t evaluations() const { return in_.evaluations; }
  /// Names of the stages that run, in pipeline order.
  std::vector<std::string> stage_names() const;
  /// Time per part of the evaluation: [0] is the neighbour search, then the stages in pipeline order.
  const std::vector<StageTiming>& timings() const { return in_.timings; }
  /// Effective eta (the kernel's default if kernel.eta == 0).
  double eta() const { return in_.eta; }
  double spacing() const { return in_.spacing; }              ///< the scene's initial particle spacing
  double wall_strength() const { return in_.wall_strength; }  ///< the scene's Lennard-Jones D (walls.D = 0)

 private:
  StageContext context() const;

  Inputs in_;
};

}  // namespace sph

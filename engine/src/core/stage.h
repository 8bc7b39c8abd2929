// A stage of the step pipeline: one option of one slot of sph::Physics (density summation, the Tait
// EOS, XSPH, Lennard-Jones walls, ...). World::evaluate runs the scene's stages in pipeline order; each
// declares the fields it reads, writes and evolves (so only those are allocated), copies to the ghosts
// what its neighbours read, contributes its timestep limit and, for conservative forces, a potential.
// Stages whose per-pair maths is fused into the force loop for speed (viscosity, conduction, the
// energy equation) are stages too: they declare their fields, limits and evolved pairs and run nothing.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "sph/density.h"
#include "sph/domain.h"
#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

/// Counters the stages fill during one evaluation (reported in the diagnostics).
struct EvalStats {
  DensityStats density;                 ///< the summation density / h solve, or neighbour counts
  std::size_t correction_fallbacks = 0; ///< particles whose gradient correction fell back to L = I
  ProjectionStats projection;           ///< DFSPH's solves (zero without)
};

/// What a stage sees: constant configuration, the particles and the neighbour lists of this evaluation.
struct StageContext {
  const Params& prm;
  const Kernel& kernel;
  const Domain& domain;
  Particles& p;
  /// Every j within support max(h_i, h_j) of each real i, in a fixed order; with pairs beyond that too
  /// (up to the lists' skin) unless the stage asks for exact_lists().
  const NeighbourList& nl;
  const std::vector<double>& h_limit;  ///< the largest h each particle's list covers [length]
  double eta;                          ///< effective eta of h = eta (m/rho)^(1/d)
  double spacing;                      ///< the scene's initial particle spacing [length]
  double wall_strength;                ///< the scene's Lennard-Jones D [length^2/time^2]
  EvalStats& stats;
  double since = 0.0;                  ///< time since the last evaluation [time]; 0 when unknown
  /// With individual time steps (time.levels > 1): the fluid particles whose step ends now, in increasing
  /// index; the others keep their rates, and a stage may skip them. Null: every particle.
  const std::vector<std::uint32_t>* active = nullptr;
  /// The rows a per-particle loop over the first n fluid particles visits: row(k) for k < rows(n).
  std::size_t rows(std::size_t n) const { return active ? active->size() : n; }
  std::size_t row(std::size_t k) const { return active ? (*active)[k] : k; }
  /// With individual time steps: the particles whose density the active ones read (they and their
  /// neighbours, in increasing index), so that no force sees a density older than the step. Null: all.
  const std::vector<std::uint32_t>* summed = nullptr;
  std::size_t summed_rows(std::size_t n) const { return summed ? summed->size() : n; }
  std::size_t summed_row(std::size_t k) const { return summed ? (*summed)[k] : k; }
  /// Wall particles take part in the SPH sums (dummy walls) or only exert their own force (Lennard-Jones).
  bool walls_in_sums() const { return prm.physics.walls == WallType::Dummy; }
};

/// An evolved state field and the field holding its time derivative (e.g. rho and drho/dt).
using EvolvedPair = std::pair<Field, Field>;

/// What a stage declares to the pipeline: its name and the fields it reads, computes and shares.
struct StageContract {
  std::string_view name;
  /// Fields read (they must be allocated; some other stage or the scene writes them).
  FieldSet needs = {};
  /// Fields computed at every evaluation.
  FieldSet writes = {};
  /// Of those, the ones neighbours read: copied to the ghosts after run().
  FieldSet shares = {};
};

class Stage {
 public:
  static constexpr double kNoLimit = std::numeric_limits<double>::infinity();
  virtual ~Stage() = default;
  /// The contract the stage was built with (StageContract).
  std::string_view name() const { return contract_.name; }
  FieldSet needs() const { return contract_.needs; }
  FieldSet writes() const { return contract_.writes; }
  FieldSet shares() const { return contract_.shares; }
  /// State fields advanced by the integrator, with their rates.
  virtual std::vector<EvolvedPair> evolves() const { return {}; }
  /// False if the stage never reads the neighbour lists (self-gravity, a body force): a pipeline of
  /// such stages only builds no lists.
  virtual bool uses_neighbours() const { return true; }
  /// True if the stage uses every entry of its lists as a neighbour. Lists are kept between
  /// evaluations with a skin (Verlet lists): they hold pairs somewhat beyond the support, which the
  /// stages that test the distance (all the SPH loops) skip; a stage that does not gets lists filtered
  /// to the pairs within the support at every evaluation.
  virtual bool exact_lists() const { return false; }
  /// With individual time steps: false if the stage reads only the lists of the particles
  /// StageContext::rows and summed_rows give, so that the other lists need not be gathered; true (the
  /// safe default) for a stage whose loops visit every particle's list.
  virtual bool reads_every_list() const { return uses_neighbours(); }
  /// True if the stage sets the accelerations (the first force stage); later stages add to them.
  virtual bool sets_acceleration() const { return false; }
  /// Computes. Returns false if a particle's h outgrew its neighbour list: the world rebuilds the list
  /// from the new h and runs the stages again.
  virtual bool run(StageContext&) { return true; }
  /// Whether the stage acts on the state after step number `step` (counted from 1) has completed.
  virtual bool acts_after(const Params&, std::int64_t /*step*/) const { return false; }
  /// That action (e.g. re-initialising rho), with fresh ghosts and neighbour lists; the rates of the
  /// last evaluation are then stale and the next step evaluates first.
  virtual void after_step(StageContext&) {}
  /// After after_step(): a new set of real particles when the stage changed their number (the finite
  /// pointset method's merge/split point control); the world adopts it whole (fields, ids, kinds).
  virtual bool take_resampled(Particles&) { return false; }
  /// Largest stable dt from this stage, before the Courant factor [time].
  virtual double dt_limit(const StageContext&) const { return kNoLimit; }
  /// The same limit per fluid particle (individual time steps): dt[i] = min(dt[i], limit of i) [time].
  /// By default every particle takes the stage's global limit.
  virtual void dt_limits(const StageContext& c, std::span<double> dt) const {
    const double g = dt_limit(c);
    if (g < kNoLimit)
      for (double& d : dt) d = d < g ? d : g;
  }
  /// True for a pressure solve (DFSPH): the world then steps by project() instead of the integrator.
  virtual bool projects() const { return false; }
  /// One step of length dt [time] from the rates of the current state (non-pressure accelerations in a):
  /// the stage sets the fluid's velocities of the new step, with the pressure that keeps the density;
  /// the world then moves the particles x += dt v (symplectic Euler).
  virtual void project(StageContext&, double /*dt*/) {}
  /// Potential energy of a conservative force [energy].
  virtual double potential(const StageContext&) const { return 0.0; }
  /// Internal energy the stage stores (an EOS) [energy].
  virtual double internal_energy(const StageContext&) const { return 0.0; }
  /// State the stage keeps between evaluations that later steps depend on (checkpoints): arrays of
  /// numbers, bit for bit. Empty for a stage that keeps none.
  virtual std::vector<std::vector<double>> saved_state() const { return {}; }
  /// Takes back what saved_state() gave (of a stage of the same type). Returns false if it does not fit.
  virtual bool restore_state(const std::vector<std::vector<double>>& s) { return s.empty(); }
  /// Follows a new storage order of the particles (new index k holds old order[k], fluid first): for a
  /// stage that keeps values per particle between evaluations.
  virtual void permute(std::span<const std::uint32_t> /*order*/) {}

 protected:
  explicit Stage(StageContract contract) : contract_(contract) {}

 private:
  StageContract contract_;
};

}  // namespace sph

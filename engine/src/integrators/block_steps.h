// Individual time steps (time.levels > 1): every fluid particle steps with its own dt on a power-of-two
// level of the largest step D of a block, dt = D / 2^b with b < levels, in kick-drift-kick leapfrog
// (block time steps: GADGET-2, Springel 2005 §5; SWIFT). Time inside a block is counted in ticks of
// D / 2^(levels-1); a particle's step starts on a multiple of its length. One call of step() is one
// sub-step: every particle drifts with its half-kicked velocity, the particles whose step ends now are
// evaluated (the stages see them as StageContext::active) and kicked, and they take new levels.
// The others are predicted, v = v_1/2 + a_0 (t - t_mid), and keep the rates of their last evaluation.
// Neighbours stay within two levels (Saitoh & Makino 2009, ApJ 697, L99): a particle's level (its
// wanted step) is at most four times the shortest level among its neighbours, and a particle stepping
// more than four times its neighbour's new level is woken: its step ends now, its opening kick cut back
// to the time it has run (Durier & Dalla Vecchia 2012, MNRAS 419, 465), as when a shock reaches cold
// gas. A step starts on a multiple of its length, so a particle woken at an odd tick steps one tick
// and grows back to its level; the limiter compares levels, so the wake spreads only as far as the
// levels need.
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "sph/integrator.h"
#include "sph/neighbours.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

/// Why these parameters cannot step particles individually (time.levels > 1), naming the keys; empty
/// when they can.
std::string block_steps_refusal(const Params& p);

class BlockSteps {
 public:
  explicit BlockSteps(int levels);

  /// What a sub-step asks of the world.
  struct Hooks {
    /// Rates of the active() particles for the state at `offset` after the sub-step's start [time].
    std::function<void(double offset)> eval;
    /// Every fluid particle's wanted dt from its latest rates (only the active ones' are read) [time].
    std::function<void(std::vector<double>&)> want;
    /// The neighbour lists of the latest evaluation (the limiter's neighbours).
    std::function<const NeighbourList&()> lists;
  };

  /// Between blocks: every particle's state and rates are at the same time.
  bool synchronised() const { return !in_block_; }
  /// Inside a block: the time to the next end of a particle's step [time].
  double next_dt() const { return static_cast<double>(next_tick_ - tick_) * tau_; }
  /// Between blocks: the largest step a block would take for these wanted steps [time].
  double block_length(const std::vector<double>& want) const;
  /// One sub-step (a new block first when synchronised, of length at most dt_max); returns its length.
  /// The rates must be current for every particle when synchronised.
  double step(PhaseSpace& s, const Particles& p, const Hooks& hooks, double dt_max);
  /// Every particle's current step length and start [ticks of block_tick()].
  const std::vector<std::int64_t>& lengths() const { return len_; }
  const std::vector<std::int64_t>& starts() const { return begin_; }
  const std::vector<std::int64_t>& levels() const { return level_; }
  /// Writes each fluid particle's step level k (its step is the block / 2^k) into `level`.
  void write_levels(std::vector<double>& level) const;
  double block_tick() const { return tau_; }
  /// The particles the current evaluation is for.
  const std::vector<std::uint32_t>& active() const { return active_; }
  /// The active particles and their neighbours: the densities the active ones' forces read. Marked by
  /// the evaluation once its lists are ready (a list rebuilt for this state may hold a new neighbour).
  const std::vector<std::uint32_t>& summed() const { return summed_; }
  void mark_summed(const Particles& p, const NeighbourList& nl);
  /// Ends the block where it stands (new parameters): the particles keep their current (predicted)
  /// velocities and state, and the next step starts a block from a fresh evaluation.
  void synchronise() { in_block_ = false; }
  /// The fluid particles were reordered (slot k holds the particle that was at order[k]).
  void permute(std::span<const std::uint32_t> order);
  /// The block's state for a checkpoint (bit for bit), and its restore (false if it does not fit).
  std::vector<std::vector<double>> history() const;
  bool set_history(const std::vector<std::vector<double>>& h);
  /// Particle steps since the last call that took the block's shortest level though they wanted less
  /// than half of it: the flow sped up inside a block (the block's shortest level is the shortest
  /// wanted step at its start).
  std::int64_t take_too_long() { const std::int64_t k = too_long_; too_long_ = 0; return k; }

 private:
  void begin_block(PhaseSpace& s, const Particles& p, const Hooks& hooks, double dt_max);
  /// The particles whose step ends at tick_, and those a neighbour wakes (their step cut to end now).
  void mark_active(PhaseSpace& s);
  /// New step lengths of the active particles from their wanted dt, aligned and limited.
  void choose_levels(const Particles& p, const NeighbourList& nl, const std::vector<double>& want);
  /// Opening half kick of the active particles: v_1/2 = v + a len tau / 2 (and the evolved state).
  void open(const PhaseSpace& s);
  void find_next_tick();

  int levels_;
  std::int64_t ticks_;  ///< ticks in a block: 2^(levels-1)
  bool in_block_ = false;
  std::int64_t tick_ = 0, next_tick_ = 0;
  double tau_ = 0.0;  ///< tick length [time]
  std::int64_t too_long_ = 0;
  std::vector<std::int64_t> len_, begin_;  ///< each particle's step length and start [ticks]
  /// Each particle's level: the step its wanted dt and its neighbours' levels allow, before it is
  /// shortened to start on a multiple of itself [ticks]. The limiter and the wake compare levels.
  std::vector<std::int64_t> level_;
  std::vector<std::uint8_t> on_;           ///< active mask
  std::vector<std::uint32_t> active_, summed_;
  std::vector<std::uint8_t> near_;  ///< summed mask
  std::vector<std::uint8_t> wake_;  ///< inactive particles a neighbour's new short step wakes next
  std::array<std::vector<double>, 3> vhalf_, a0_;  ///< half-kicked v and the a of the opening kick
  std::vector<std::vector<double>> yhalf_, r0_;     ///< the same for the evolved state and its rates
};

}  // namespace sph

// Time integrators over the particle phase space: x, v and whatever the stages evolve (u with the
// energy equation, rho with the continuity equation). Particles drift with v, or with v plus an XSPH
// correction when the scene has one. Chosen at runtime by IntegratorType; each is a small class in
// src/integrators/.
#pragma once
#include <array>
#include <functional>
#include <span>
#include <memory>
#include <vector>

#include "sph/params.h"

namespace sph {

/// A state array advanced with its rate: y' = rate (first n entries).
struct EvolvedArray {
  std::vector<double>* y = nullptr;
  std::vector<double>* rate = nullptr;
};

/// Views of the evolved arrays (first n entries of each: the moving particles) and their derivatives.
struct PhaseSpace {
  int dim = 1;
  std::size_t n = 0;
  std::array<std::vector<double>*, 3> x{}, v{}, a{};
  /// dx/dt = v + drift when set (XSPH, seed 001 eq. 47); refreshed by every evaluation.
  std::array<std::vector<double>*, 3> drift{};
  std::vector<EvolvedArray> evolved;
  bool drifts() const { return drift[0] != nullptr; }
};

/// Recomputes a, the drift and the evolved rates from the current state, which the integrator has put
/// at `offset` [time] after the start of the step (0 for the state it started from).
using Evaluate = std::function<void(double offset)>;

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances the phase space by dt. `current` says whether the rates already belong to the current
  /// state (then integrators that start with an evaluation skip it). Returns whether the rates belong
  /// to the new state on return.
  virtual bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) = 0;
  /// Drops internal history (after a reset, a change of particle count or of the evolved set).
  virtual void reset() {}
  /// The particles were reordered (slot k now holds the particle that was at order[k]): history kept
  /// per particle between steps must follow them.
  virtual void permute(std::span<const std::uint32_t> order) { (void)order; }
  /// History kept between steps that the next step uses (checkpoints): arrays of numbers, bit for bit;
  /// empty when there is none.
  virtual std::vector<std::vector<double>> history() const { return {}; }
  /// Takes back what history() gave (an integrator of the same type). Returns false if it does not fit.
  virtual bool set_history(const std::vector<std::vector<double>>& h) { return h.empty(); }
};

std::unique_ptr<Integrator> make_integrator(IntegratorType type);

}  // namespace sph

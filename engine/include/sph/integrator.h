// Time integrators over the particle phase space (x, v and, when the scene has an energy equation, u).
// Chosen at runtime by IntegratorType; each is a small class in src/integrators/.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "sph/params.h"

namespace sph {

/// Views of the evolved arrays (first n entries of each) and of their time derivatives.
struct PhaseSpace {
  int dim = 1;
  std::size_t n = 0;
  std::array<std::vector<double>*, 3> x{}, v{}, a{};
  std::vector<double>* u = nullptr;     ///< specific internal energy, or null
  std::vector<double>* dudt = nullptr;  ///< its rate, or null
};

/// Recomputes a (and du/dt) from the current x, v, u.
using Evaluate = std::function<void()>;

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances the phase space by dt. `current` says whether a and du/dt already belong to the current
  /// state (then integrators that start with an evaluation skip it). Returns whether a and du/dt belong
  /// to the new state on return.
  virtual bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) = 0;
  /// Drops internal history (after a reset or a change of particle count).
  virtual void reset() {}
};

std::unique_ptr<Integrator> make_integrator(IntegratorType type);

}  // namespace sph

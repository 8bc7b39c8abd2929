// The simulation: particles, boundaries, the active modules and an integrator. Headless runs and tests
// call step() directly (no threads); the GUI's stepper thread owns one World.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "sph/config.h"
#include "sph/density.h"
#include "sph/diagnostics.h"
#include "sph/integrator.h"
#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/snapshot.h"

namespace sph {

/// A NaN or inf appeared in the state: which particle (id), which field, at which step.
struct DivergedError : std::runtime_error {
  DivergedError(std::int64_t particle, std::int64_t step, double t, const std::string& field);
  std::int64_t particle, step;
  double t;
  std::string field;
};

class World {
 public:
  explicit World(const RunConfig& cfg);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adopt new run parameters; live ones take effect at the next step (kernel, eta, alpha, ...).
  void set_params(const Params& p);
  const Params& params() const { return cfg_.params; }
  const RunConfig& config() const { return cfg_; }
  const SceneSpec& scene() const { return *cfg_.scene; }

  /// One step of the adaptive (or fixed) dt, shortened to at most dt_max. Throws DivergedError.
  void step(double dt_max = 1e300);
  /// Steps until time t (the last step is shortened to land on t exactly).
  void advance_to(double t);
  /// The timestep the next step would take (from the last force evaluation).
  double next_dt();

  double time() const { return t_; }
  std::int64_t steps() const { return step_; }
  double last_dt() const { return dt_last_; }
  const Particles& particles() const { return p_; }
  const Domain& domain() const { return domain_; }
  const Kernel& kernel() const { return kernel_; }
  double eta() const;  ///< effective eta (the kernel's default if params.eta == 0)
  const DensityStats& density_stats() const { return dstats_; }
  std::int64_t evaluations() const { return evaluations_; }

  Diagnostics diagnostics() const;
  bool has_reference() const { return reference_ != nullptr; }
  const Reference* reference() const { return reference_.get(); }
  ErrorNorms errors() const;  ///< L1 norms against the reference (zeros if none)
  /// Copy of what a viewer needs (floats): positions, h, every display field, reference curves.
  Snapshot snapshot() const;

  /// Evaluate densities and forces for the current state (done automatically by step()).
  void evaluate();

 private:
  void check_finite() const;

  RunConfig cfg_;
  Kernel kernel_;
  Particles p_;
  Domain domain_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<Reference> reference_;
  NeighbourList nl_;
  DensityStats dstats_;
  std::vector<double> h_limit_;
  double t_ = 0.0, dt_last_ = 0.0;
  std::int64_t step_ = 0, evaluations_ = 0;
  bool current_ = false;      ///< accelerations belong to the current state
  bool rates_known_ = false;  ///< signal speeds from some evaluation under the current params (for dt)
};

}  // namespace sph

// A scene is a description: name, dimension, the physics modules it turns on, default parameters,
// its own parameters (particle counts, states), a function that places the particles, and optionally
// an exact or reference solution. Built-in scenes live in an explicit table (scenes/registry.cpp).
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sph/domain.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

/// Physics modules a scene opts into; each needs a set of fields (modules.cpp).
struct Modules {
  bool hydro = true;         ///< summation density, grad-h, pressure forces (seed 000 §3.3)
  bool energy = true;        ///< internal energy equation (seed 000 eq. 3.3.19)
  bool viscosity = true;     ///< Monaghan artificial viscosity (seed 003 eq. 3.16)
  bool conductivity = false; ///< artificial thermal conductivity (Price 2008)
};

/// Fields the enabled modules need.
FieldSet fields_for(const Modules& m);

/// A number the scene itself takes (e.g. particles per side); key "scene.<name>" in files and --set.
struct SceneParam {
  std::string name;
  double value = 0.0;
  double min = 0.0, max = 0.0;
  bool integer = false;
  std::string description;
};

using SceneValues = std::map<std::string, double>;

/// What a scene's build function returns: the particles (with m, h guess, u, v set) and the box.
struct SceneSetup {
  Particles particles;
  Domain domain;
};

/// Exact or reference solution of a 1D scene (e.g. a Riemann problem), sampled at (x, t).
class Reference {
 public:
  virtual ~Reference() = default;
  struct State { double rho, v, p, u; };
  virtual State at(double x, double t) const = 0;
  /// Particles used in error norms: x in [lo, hi] (away from boundary effects).
  virtual double window_lo() const = 0;
  virtual double window_hi() const = 0;
};

struct SceneSpec {
  std::string name;
  std::string category;     ///< e.g. "gas dynamics / shock tubes"
  std::string description;  ///< one line for `sph list`
  int dim = 1;
  Modules modules;
  Params defaults;                       ///< the scene's default run parameters
  std::vector<SceneParam> params;        ///< the scene's own parameters with defaults and ranges
  std::function<SceneSetup(const Params&, const SceneValues&)> build;
  std::function<std::unique_ptr<Reference>(const Params&, const SceneValues&)> reference;  ///< may be empty
  /// Optional density anchor: a particle index in a uniform region and the density it should have. All
  /// masses are scaled once so that its summation density equals that target: this removes the kernel's
  /// lattice bias (M4 in 1D sums to ~0.999 rho) from the initial state. On a uniform lattice the
  /// self-consistent rho scales exactly with m at fixed eta, so one scaling is exact.
  std::function<std::pair<std::size_t, double>(const SceneValues&)> density_anchor;
  /// Optional initial pressure P(x): after the first density sum, u is set to P/((gamma-1) rho) so the
  /// initial pressure is exactly P even where summation smooths rho (no start-up pressure blip).
  std::function<double(const Vec3&, const SceneValues&)> initial_pressure;

  SceneValues default_values() const;
};

/// All built-in scenes, in display order.
const std::vector<SceneSpec>& scene_registry();
const SceneSpec* find_scene(std::string_view name);

}  // namespace sph

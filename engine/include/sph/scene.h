// A scene is a description: name, dimension, the physics stages it runs (in its default parameters),
// its own parameters (particle counts, states), a function that places the particles, and optionally
// an exact or reference solution. Built-in scenes: files of engine/scenes/ with SPH_SCENE markers (table generated).
#pragma once
#include <array>
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
#include "sph/reference.h"
#include "sph/view_inset.h"

namespace sph {

/// A number the scene itself takes (e.g. particles per side); key "scene.<name>" in files and --set.
struct SceneParam {
  std::string name;
  double value = 0.0;
  double min = 0.0, max = 0.0;
  bool integer = false;
  std::string description;
  std::string unit;  ///< of value: "m", "count", "length/time", ... or "dimensionless"
};

using SceneValues = std::map<std::string, double>;

/// What one unit of a scene's numbers is in cgs (the /Units group of HDF5 files and the unit block of
/// the parameter files export-ics writes). Gas tests are in code units (1, 1, 1): only ratios matter.
struct UnitSystem {
  std::string name = "code units";
  double length_cgs = 1.0;  ///< one length unit [cm]
  double mass_cgs = 1.0;    ///< one mass unit [g]
  double time_cgs = 1.0;    ///< one time unit [s]
  /// SI: m, kg, s (the liquids of seed 001).
  static UnitSystem si() { return {"SI (m, kg, s)", 100.0, 1000.0, 1.0}; }
  /// AU, solar mass, Julian year (the N-body scenes of seed 003: G = 4 pi^2); IAU 2012 au, IAU 2015 nominal
  /// solar mass parameter over G.
  static UnitSystem astronomical() { return {"AU, Msun, yr", 1.495978707e13, 1.98847e33, 3.15576e7}; }
};

/// What a scene's build function returns: the particles (with kinds, m, h guess, v and the state the
/// stages start from set) and the box.
struct SceneSetup {
  Particles particles;
  Domain domain;
  double spacing = 0.0;        ///< initial particle spacing [length] (Lennard-Jones r0 when walls.r0 = 0)
  double wall_strength = 0.0;  ///< Lennard-Jones D [length^2/time^2] when walls.D = 0 (seed 001: ~5 g H)
};

/// The convergence study `sph converge SCENE` runs when not told otherwise: one key over a list of
/// values, errors taken at time t (< 0: the scene's t_end).
struct ConvergenceDefaults {
  std::string key;
  std::vector<double> values;
  double t = -1.0;
  std::string column;  ///< the reference column compared (empty: its primary error)
};

/// A bound on one of the reference's error norms (a column of errors.csv) that a correct run of the
/// scene keeps: measured at the defaults, with margin. At each output a value beyond it is warned about
/// (RunChecks::check_error_bounds), naming the column.
struct ErrorBound {
  std::string column;
  double max = 0.0;   ///< in the column's unit
  double from = 0.0;  ///< checked from this time on (e.g. the end of a relaxation) [time]
};

/// What the reference assumes of one value, a scene value ("scene.NAME") or a numeric parameter key:
/// its comparison means what it says, and the error bounds apply, for lo <= value <= hi. Outside, the
/// run warns at the start (RunChecks::check_assumptions), naming the key, the range and `why`.
struct RefAssumption {
  std::string key;
  double lo = 0.0, hi = 0.0;
  std::string why;  ///< e.g. "the Kepler orbit is that of point masses"
  /// A derived value (e.g. a ratio of scene values), which `key` then names; empty: the key's value.
  std::function<double(const Params&, const SceneValues&)> value;
};
/// "= lo", ">= lo" (hi of 1e300 or more) or "in [lo, hi]", for messages.
std::string range_text(const RefAssumption& a);

struct SceneSpec {
  std::string name;
  std::string category;     ///< e.g. "gas dynamics / shock tubes"
  std::string description;  ///< one line for `sph list`
  int dim = 1;
  Params defaults;                       ///< the scene's default run parameters, its physics included
  /// Per slot, the options this scene accepts (empty: any combination Physics::validate accepts; for
  /// the gravity slot, empty means none only).
  std::array<std::vector<std::string>, kSlotCount> allowed;
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
  /// Energy conservation a correct run keeps: |E_tot - E_tot(step 1)| over the initial energy scale
  /// |E_kin| + |E_int| + |E_pot| stays below this (measured at the defaults, with margin; README). A
  /// run beyond it gets an "energy" warning, beyond 100 times it (at most 0.1) it stops as unstable
  /// (checked every step; every 16 steps with gravity).
  /// 0: the scene does not conserve energy (walls doing work, damping, physical viscosity...).
  double energy_bound = 0.0;
  /// The reference's error bounds and its assumptions (the reference guard; README "Warnings").
  std::vector<ErrorBound> error_bounds;
  std::vector<RefAssumption> assumptions;
  ConvergenceDefaults convergence;  ///< empty key: scene.n over 60 ... 1920 if the scene has n
  UnitSystem units;                 ///< what the scene's numbers are in (code units unless set)
  ViewInset inset;                  ///< 2D: a region drawn enlarged in a corner of the plane view (half 0: none)

  SceneValues default_values() const;
  /// Restricts a slot to these options.
  void allow(Slot s, std::vector<std::string> options) { allowed[static_cast<std::size_t>(s)] = std::move(options); }
  bool allows(Slot s, const std::string& option) const;
};

/// All built-in scenes, in display order.
const std::vector<SceneSpec>& scene_registry();
const SceneSpec* find_scene(std::string_view name);

}  // namespace sph

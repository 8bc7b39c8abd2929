// What a scene is checked against: an exact solution, an ODE or measured data. A reference reports
// named values at time t (measurements from the particles, their exact counterparts, error norms) and
// the exact curves to draw over the particles. errors.csv, the GUI's plots and the headless overlays
// take whatever it returns.
#pragma once
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sph/domain.h"
#include "sph/particles.h"
#include "sph/snapshot.h"

namespace sph {

struct RefColumn {
  std::string name;         ///< column of errors.csv, e.g. "L1_rho", "major", "major_exact"
  std::string description;  ///< one line with the unit, for tooltips
  bool error = false;       ///< an error norm (smaller is better) rather than a measurement
};

/// Curves of the exact solution at one time.
struct ReferenceCurves {
  std::vector<ExactCurve> profiles;  ///< field against a coordinate (1D profile plots)
  std::vector<Outline> outlines;     ///< shapes in the plane (2D views)
};

class Reference {
 public:
  virtual ~Reference() = default;
  /// The columns, the same at every time.
  virtual std::vector<RefColumn> columns() const = 0;
  /// Their values for the real particles at time t (one per column).
  virtual std::vector<double> evaluate(const Particles& p, double t) const = 0;
  /// What is compared, and how: the comment line at the head of errors.csv.
  virtual std::string description() const = 0;
  /// Exact curves to draw at time t (none by default).
  virtual ReferenceCurves curves(const Domain&, double) const { return {}; }
  /// The column plotted as "the error" against time.
  virtual int primary() const { return 0; }
  /// The time up to which the comparison means what it says (e.g. until a wave reaches a wall and the
  /// unbounded exact solution no longer applies); infinity when it always applies.
  virtual double valid_until() const { return std::numeric_limits<double>::infinity(); }
  /// Why the comparison stops there, for the run's warning.
  virtual std::string valid_until_reason() const { return "waves have reached a boundary"; }
  /// Measured/exact column pairs the GUI plots together against time (e.g. the drop's semi-axes).
  virtual std::vector<std::pair<int, int>> series() const { return {}; }
  /// What later values depend on besides the particles and t (e.g. a fit over every evaluation so far),
  /// bit for bit, for checkpoints; empty when nothing.
  virtual std::vector<double> saved_state() const { return {}; }
  /// Takes back what saved_state() gave. Returns false if it does not fit.
  virtual bool restore_state(const std::vector<double>& s) { return s.empty(); }
};

/// Index of a column by name, or -1.
int find_column(const std::vector<RefColumn>& columns, const std::string& name);

}  // namespace sph

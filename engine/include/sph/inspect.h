// One particle taken apart (Report::inspect): its fields, its neighbours with their kernel weights, and
// the terms of its momentum and energy equations for the scene's formulation, re-evaluated at the
// current state with the engine's own stages. Enough to answer "why did this particle heat up?".
// Plain values: the engine fills it, a viewer shows it; nothing here refers to a GUI.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "sph/vec.h"

namespace sph {

/// A neighbour of the inspected particle a (inside the support of max(h_a, h_b)), in list order.
struct InspectNeighbour {
  std::int64_t id = -1;   ///< particle id (a ghost reports the id of its source)
  bool ghost = false;     ///< a periodic image or wall mirror of particle `id`
  bool wall = false;      ///< a wall particle (or its image)
  Vec3 x;                 ///< where the pair term sees it (a ghost: the image position) [length]
  double r = 0.0;         ///< |x_a - x_b| [length]
  double W = 0.0;         ///< W(r, h_a), the kernel weight [1/length^d]
  double share = 0.0;     ///< m_b W(r, h_a) / rho_a: its part of a's summation density [dimensionless]
  Vec3 a;                 ///< its pair contribution to dv_a/dt (all force terms) [length/time^2]
  double dudt = 0.0;      ///< its pair contribution to du_a/dt [length^2/time^3]
};

/// One term of the particle's equations of motion: a pair sum of the force stage (pressure, artificial
/// viscosity, conduction...), or the whole contribution of a later stage (walls, body force, gravity).
struct InspectTerm {
  std::string name;       ///< "pressure", "artificial viscosity Pi", "body force g", ...
  std::string source;     ///< the stage and the equation it implements
  Vec3 a;                 ///< contribution to dv/dt [length/time^2]
  double dudt = 0.0;      ///< contribution to du/dt [length^2/time^3]
  /// sum over pairs of |pair contribution to a| (a stage's |a| for a whole-stage term): the size the
  /// term's round-off is measured against [length/time^2]
  double a_scale = 0.0;
  double dudt_scale = 0.0;  ///< the same for du/dt [length^2/time^3]
};

struct Inspection {
  std::int64_t id = -1;
  std::int64_t step = 0;  ///< of the state inspected
  double t = 0.0;
  bool wall = false;
  std::string formulation;  ///< the force stage whose terms are listed (empty: no force stage)
  Vec3 x, v;
  // the run's values of its fields (NaN where the scene's stages do not allocate one)
  double m = 0.0, rho = 0.0, P = 0.0, u = 0.0, h = 0.0, omega = 0.0, c = 0.0, speed = 0.0;
  double neighbours = 0.0;    ///< inside its own support (self included), from the last evaluation
  double support = 0.0;       ///< radius of its kernel's support, the kernel's support() times h [length]
  double h_iterations = 0.0;  ///< Newton-Raphson iterations of its last h solve
  double drhodt = 0.0;        ///< continuity rate [mass/(length^d time)]
  std::vector<InspectNeighbour> neighbour_list;
  std::vector<InspectTerm> terms;
  /// The rates of the re-evaluation at the current state, which the terms add up to.
  Vec3 a_total;
  double dudt_total = 0.0;
  /// The rates the run holds: from its last evaluation (a leapfrog step evaluates at the predicted
  /// velocity, so these differ from a_total by O(dt) where forces depend on v).
  Vec3 a_stored;
  double dudt_stored = 0.0;
  bool has_energy = false;  ///< the scene evolves u (du/dt terms are meaningful)
};

}  // namespace sph

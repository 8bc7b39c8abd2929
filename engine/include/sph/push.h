// A transient push by the user (the GUI's right-drag): a body force on the fluid particles near a point
// that drags them along with a velocity,
//   a_push = w(r/R) (v_push - v) / tau,   w(q) = (1 - q^2)^2 for q < 1, else 0,
// r the (minimum-image) distance to the push centre. Added to the accelerations after the stages at every
// force evaluation (World::evaluate), so every integrator applies it the same way. No push = no change.
// Pushes are recorded with the step they apply from, so that a run can be replayed (PushReplay).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/vec.h"

namespace sph {

class Particles;
struct Domain;
class World;

struct Push {
  std::array<double, 3> x{0, 0, 0};  ///< centre [length]
  std::array<double, 3> v{0, 0, 0};  ///< velocity the particles are dragged to [length/time]
  double radius = 0.0;               ///< R: the push acts within this distance [length]; 0 = no push
  double tau = 0.0;                  ///< relaxation time towards v [time]
  bool active() const { return radius > 0.0 && tau > 0.0; }
  bool operator==(const Push& o) const { return x == o.x && v == o.v && radius == o.radius && tau == o.tau; }
  bool operator!=(const Push& o) const { return !(*this == o); }
};

/// A push set before step `step` (World::steps() == step when it was set); it holds until the next event.
/// An inactive push (radius 0) ends a push.
struct PushEvent {
  std::int64_t step = 0;
  Push push;
};

/// The compact weight w(q) = (1 - q^2)^2 for 0 <= q < 1, 0 beyond (dimensionless).
double push_weight(double q);

/// a_push of one particle at x moving with v [length/time^2] (zero beyond R, and in the axes >= dim).
Vec3 push_acceleration(const Push& push, const Domain& d, int dim, const Vec3& x, const Vec3& v);

/// Adds a_push (above) to the accelerations of the fluid particles of p [length/time^2]; periodic axes
/// of d measure distances by the nearest image. Does nothing for an inactive push.
void add_push_acceleration(const Push& push, const Domain& d, Particles& p);

/// Replays a recorded sequence of pushes: call before every World::step; sets each event on the World
/// when the World reaches its step. Events must be in increasing step order.
class PushReplay {
 public:
  explicit PushReplay(std::vector<PushEvent> events) : events_(std::move(events)) {}
  void apply_due(World& w);
  bool done() const { return next_ >= events_.size(); }

 private:
  std::vector<PushEvent> events_;
  std::size_t next_ = 0;
};

}  // namespace sph

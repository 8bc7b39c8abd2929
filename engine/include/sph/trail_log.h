// Orbit trails of the few-body scenes (2D point masses, at most 64 particles): each particle's path,
// sampled after every step of the run rather than at the frames drawn, so the trail is one smooth line
// whatever the display's rate or the frame interval (sampled at the frames, a fast Kepler orbit came out
// as nine dashes, or nothing). A point is kept whenever a particle has moved kSpacing of the system's
// first extent since the last; the newest kMaxPoints per particle are kept. The trails are added to a
// snapshot as outlines labelled "orbits", ending at each particle's position, each cut to its last
// kTurns revolutions about the centre of mass: a hundred orbits of Mercury, each slightly turned, filled
// an annulus (the inner planets were one blob), one and a quarter show the orbit and its turning.
#pragma once
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "sph/snapshot.h"

namespace sph {

class World;

class TrailLog {
 public:
  static constexpr std::size_t kMaxParticles = 64, kMaxPoints = 20000;
  static constexpr double kSpacing = 2e-3;  ///< sample spacing / extent of the particles at the first sample
  static constexpr const char* kLabel = "orbits";
  static constexpr double kTurns = 1.25;  ///< revolutions about the centre of mass a trail shows at most

  /// Whether the world's particles get trails (2D, 1..kMaxParticles, no SPH density: point masses).
  static bool applies(const World& w);
  /// Samples the world's positions now (call after each step); restarts when the particle count, the
  /// scene or the run changes (time went back). Nothing for a world that has no trails.
  void record(const World& w);
  /// Forgets every trail (a new world).
  void clear();
  /// Adds the trails to s.outlines.
  void decorate(Snapshot& s) const;
  /// Vertices of particle i's trail (tests).
  std::size_t points(std::size_t i) const { return i < x_.size() ? x_[i].size() : 0; }

 private:
  std::string scene_;
  double t_last_ = -std::numeric_limits<double>::infinity();
  double spacing2_ = 0.0;                  ///< squared sample spacing [length^2]
  std::vector<std::vector<float>> x_, y_;  ///< kept samples, particles in id order
  std::vector<float> now_x_, now_y_;       ///< the latest positions (the trail's end)
  std::vector<double> m_;                  ///< masses, id order (the centre of mass)
};

}  // namespace sph

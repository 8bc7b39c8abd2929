// Orbit trails of the few-body scenes (2D, at most 64 particles, no SPH density: point masses): the
// positions each particle had at the snapshots drawn so far, kept as polylines (the last 20,000 per
// particle) and added to a snapshot's outlines under one legend row, "orbits". They restart when the
// particle count or the scene changes, or time goes back (a reset); a jump of more than 5% of the box
// between two samples breaks the line.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace sph {
struct Snapshot;
}

namespace sph::render {

class Trails {
 public:
  static constexpr std::size_t kMaxParticles = 64, kMaxPoints = 20000;
  /// Whether a snapshot gets trails.
  static bool applies(const sph::Snapshot& s);
  /// Appends the snapshot's positions (once per time: a second call at the same t adds nothing).
  void record(const sph::Snapshot& s);
  /// Adds the trails to s.outlines.
  void decorate(sph::Snapshot& s) const;
  std::size_t points() const { return x_.empty() ? 0 : x_[0].size(); }

 private:
  std::string scene_;
  double t_last_ = 0.0;
  std::vector<std::vector<float>> x_, y_;
};

}  // namespace sph::render

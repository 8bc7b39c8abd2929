#include "trails.h"

#include <cmath>

#include "sph/snapshot.h"

namespace sph::render {

bool Trails::applies(const sph::Snapshot& s) {
  return s.dim == 2 && s.count > 0 && s.count <= kMaxParticles && s.find("rho") == nullptr;
}

void Trails::record(const sph::Snapshot& s) {
  const std::size_t n = std::min(s.count, std::min(s.x.size(), s.y.size()));
  if (n != x_.size() || s.scene != scene_ || s.t < t_last_) {  // a new run: start again
    x_.assign(n, {});
    y_.assign(n, {});
    scene_ = s.scene;
  } else if (!x_.empty() && !x_[0].empty() && s.t == t_last_) {
    return;
  }
  t_last_ = s.t;
  // a jump of more than 5% of the box between two samples (the run went far between two drawn frames)
  // breaks the line: a straight chord across an orbit would be a lie
  const float dx = s.bounds[1] - s.bounds[0], dy = s.bounds[3] - s.bounds[2];
  const float jump2 = 0.0025f * (dx * dx + dy * dy);
  for (std::size_t i = 0; i < n; ++i) {  // snapshots list particles in id order
    if (x_[i].size() >= 2 * kMaxPoints) {  // keep the newest kMaxPoints
      x_[i].erase(x_[i].begin(), x_[i].begin() + static_cast<std::ptrdiff_t>(kMaxPoints));
      y_[i].erase(y_[i].begin(), y_[i].begin() + static_cast<std::ptrdiff_t>(kMaxPoints));
    }
    if (!x_[i].empty() && std::isfinite(x_[i].back())) {
      const float ex = s.x[i] - x_[i].back(), ey = s.y[i] - y_[i].back();
      if (ex * ex + ey * ey > jump2) {
        x_[i].push_back(NAN);
        y_[i].push_back(NAN);
      }
    }
    x_[i].push_back(s.x[i]);
    y_[i].push_back(s.y[i]);
  }
}

void Trails::decorate(sph::Snapshot& s) const {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (x_[i].size() < 2) continue;
    sph::Outline o;
    o.label = "orbits";
    o.x = x_[i];
    o.y = y_[i];
    s.outlines.push_back(std::move(o));
  }
}

}  // namespace sph::render

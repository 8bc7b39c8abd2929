// Orbit trails of the few-body scenes (sph/trail_log.h).
#include "sph/trail_log.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sph/world.h"

namespace sph {

bool TrailLog::applies(const World& w) {
  const Particles& p = w.particles();
  return p.dim() == 2 && p.size() > 0 && p.size() <= kMaxParticles && !p.has(Field::Density);
}

void TrailLog::clear() {
  x_.clear();
  y_.clear();
  now_x_.clear();
  now_y_.clear();
  m_.clear();
  scene_.clear();
  t_last_ = -std::numeric_limits<double>::infinity();
}

void TrailLog::record(const World& w) {
  if (!applies(w)) {
    if (!x_.empty()) clear();
    return;
  }
  const Particles& p = w.particles();
  const std::size_t n = p.size();
  const std::vector<std::uint32_t>& order = w.by_id();  // id order (the snapshot's) -> storage index
  const std::string& scene = w.config().scene->name;
  if (n != x_.size() || scene != scene_ || w.time() < t_last_) {  // a new run: start again
    clear();
    x_.assign(n, {});
    y_.assign(n, {});
    now_x_.assign(n, 0.f);
    now_y_.assign(n, 0.f);
    m_.assign(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) m_[k] = p[Field::Mass][order[k]];
    scene_ = scene;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], p.x[k][i]);
        hi[k] = std::max(hi[k], p.x[k][i]);
      }
    const double extent = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
    spacing2_ = extent > 0.0 ? kSpacing * kSpacing * extent * extent : 0.0;
  }
  t_last_ = w.time();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const float x = static_cast<float>(p.x[0][i]), y = static_cast<float>(p.x[1][i]);
    now_x_[k] = x;
    now_y_[k] = y;
    auto& xs = x_[k];
    auto& ys = y_[k];
    if (!xs.empty()) {
      const double dx = x - xs.back(), dy = y - ys.back();
      if (dx * dx + dy * dy < spacing2_) continue;
    }
    if (xs.size() >= 2 * kMaxPoints) {  // keep the newest kMaxPoints
      xs.erase(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(kMaxPoints));
      ys.erase(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(kMaxPoints));
    }
    xs.push_back(x);
    ys.push_back(y);
  }
}

namespace {

/// The first of xs, ys to keep: the newest samples that turn at most `turns` revolutions about (cx, cy).
std::size_t first_kept(const std::vector<float>& xs, const std::vector<float>& ys, double cx, double cy, double turns) {
  double turned = 0.0;
  std::size_t k = xs.size() - 1;
  double last = std::atan2(ys[k] - cy, xs[k] - cx);
  while (k > 0) {
    const double a = std::atan2(ys[k - 1] - cy, xs[k - 1] - cx);
    double d = a - last;  // unwrapped
    if (d > std::numbers::pi) d -= 2.0 * std::numbers::pi;
    if (d < -std::numbers::pi) d += 2.0 * std::numbers::pi;
    turned += d;
    if (std::abs(turned) > 2.0 * std::numbers::pi * turns) break;
    last = a;
    --k;
  }
  return k;
}

}  // namespace

void TrailLog::decorate(Snapshot& s) const {
  double mass = 0.0, cx = 0.0, cy = 0.0;  // the centre of mass now
  for (std::size_t k = 0; k < m_.size() && k < now_x_.size(); ++k) {
    mass += m_[k];
    cx += m_[k] * now_x_[k];
    cy += m_[k] * now_y_[k];
  }
  if (mass > 0.0) cx /= mass, cy /= mass;
  for (std::size_t k = 0; k < x_.size(); ++k) {
    if (x_[k].empty()) continue;
    Outline o;
    o.label = kLabel;
    const auto first = static_cast<std::ptrdiff_t>(first_kept(x_[k], y_[k], cx, cy, kTurns));
    o.x.assign(x_[k].begin() + first, x_[k].end());
    o.y.assign(y_[k].begin() + first, y_[k].end());
    if (o.x.back() != now_x_[k] || o.y.back() != now_y_[k]) {  // up to where the particle is now
      o.x.push_back(now_x_[k]);
      o.y.push_back(now_y_[k]);
    }
    if (o.x.size() >= 2) s.outlines.push_back(std::move(o));
  }
}

}  // namespace sph

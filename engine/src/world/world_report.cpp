// What the world reports: conserved quantities (seed 000 eqs. 3.4.1–3.4.5), error norms, snapshots.
#include <algorithm>
#include <cmath>

#include "sph/world.h"

namespace sph {

Diagnostics World::diagnostics() const {
  Diagnostics d;
  d.step = step_;
  d.t = t_;
  d.dt = dt_last_;
  const auto& m = p_[Field::Mass];
  const bool has_u = p_.has(Field::Energy);
  for (std::size_t i = 0; i < p_.size(); ++i) {  // serial sums: identical for any thread count
    const Vec3 r = p_.pos(i), v = p_.vel(i);
    d.E_kin += 0.5 * m[i] * v.norm2();
    if (has_u) d.E_int += m[i] * p_[Field::Energy][i];
    const Vec3 L = r.cross(v * m[i]);
    d.P[0] += m[i] * v.x; d.P[1] += m[i] * v.y; d.P[2] += m[i] * v.z;
    d.L[0] += L.x; d.L[1] += L.y; d.L[2] += L.z;
    d.v_max = std::max(d.v_max, v.norm());
  }
  d.E_tot = d.E_kin + d.E_int + d.E_pot;
  d.h_iter_mean = dstats_.mean_iterations;
  d.h_iter_max = dstats_.max_iterations;
  d.h_not_converged = dstats_.not_converged;
  d.neighbours_mean = dstats_.mean_neighbours;
  return d;
}

ErrorNorms World::errors() const {
  ErrorNorms e;
  e.t = t_;
  if (!reference_) return e;
  const auto& rho = p_[Field::Density];
  const auto& P = p_[Field::Pressure];
  const auto& u = p_[Field::Energy];
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const double x = p_.x[0][i];
    if (x < reference_->window_lo() || x > reference_->window_hi()) continue;
    const Reference::State s = reference_->at(x, t_);
    const double drho = std::abs(rho[i] - s.rho);
    e.L1_rho += drho;
    e.L1_v += std::abs(p_.v[0][i] - s.v);
    e.L1_p += std::abs(P[i] - s.p);
    e.L1_u += std::abs(u[i] - s.u);
    e.Linf_rho = std::max(e.Linf_rho, drho);
    ++e.count;
  }
  if (e.count) {
    e.L1_rho /= e.count; e.L1_v /= e.count; e.L1_p /= e.count; e.L1_u /= e.count;
  }
  return e;
}

Snapshot World::snapshot() const {
  Snapshot s;
  const std::size_t n = p_.size();
  s.scene = cfg_.scene->name;
  s.dim = p_.dim();
  s.step = step_;
  s.t = t_;
  s.dt = dt_last_;
  s.count = n;
  s.x.resize(n); s.y.resize(n); s.z.resize(n); s.h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = static_cast<float>(p_.x[0][i]);
    s.y[i] = static_cast<float>(p_.x[1][i]);
    s.z[i] = static_cast<float>(p_.x[2][i]);
    s.h[i] = static_cast<float>(p_[Field::H][i]);
  }
  for (int k = 0; k < 3; ++k) {
    s.bounds[2 * k] = static_cast<float>(domain_.lo[k]);
    s.bounds[2 * k + 1] = static_cast<float>(domain_.hi[k]);
  }
  auto add = [&](std::string name, std::string label, auto&& value) {
    SnapshotField f;
    f.name = std::move(name);
    f.label = std::move(label);
    f.values.resize(n);
    bool first = true;
    for (std::size_t i = 0; i < n; ++i) {
      const float v = static_cast<float>(value(i));
      f.values[i] = v;
      if (!std::isfinite(v)) continue;
      if (first) { f.min = f.max = v; first = false; }
      f.min = std::min(f.min, v);
      f.max = std::max(f.max, v);
    }
    s.fields.push_back(std::move(f));
  };
  for (Field fld : {Field::Density, Field::Pressure, Field::Energy, Field::H, Field::SoundSpeed, Field::Neighbours,
                    Field::Omega}) {
    if (!p_.has(fld)) continue;
    const auto& a = p_[fld];
    add(std::string(info(fld).key), std::string(info(fld).label), [&](std::size_t i) { return a[i]; });
  }
  add("speed", "speed |v|", [&](std::size_t i) { return p_.vel(i).norm(); });
  if (s.dim == 1) add("vx", "velocity v_x", [&](std::size_t i) { return p_.v[0][i]; });
  if (reference_) {
    const int samples = 801;
    const double lo = domain_.lo[0], hi = domain_.hi[0];
    ExactCurve rho{"rho", {}, {}}, pr{"p", {}, {}}, u{"u", {}, {}}, vx{"vx", {}, {}}, sp{"speed", {}, {}};
    for (int k = 0; k < samples; ++k) {
      const double x = lo + (hi - lo) * k / (samples - 1);
      const Reference::State st = reference_->at(x, t_);
      for (ExactCurve* c : {&rho, &pr, &u, &vx, &sp}) c->x.push_back(static_cast<float>(x));
      rho.value.push_back(static_cast<float>(st.rho));
      pr.value.push_back(static_cast<float>(st.p));
      u.value.push_back(static_cast<float>(st.u));
      vx.value.push_back(static_cast<float>(st.v));
      sp.value.push_back(static_cast<float>(std::abs(st.v)));
    }
    s.exact = {rho, pr, u, vx, sp};
  }
  return s;
}

}  // namespace sph

// What the world reports: conserved quantities (seed 000 eqs. 3.4.1–3.4.5), the reference's values and
// curves, and snapshots with the scene's active fields.
#include <algorithm>
#include <cmath>

#include "core/pipeline.h"
#include "core/stage.h"
#include "sph/world.h"

namespace sph {

Diagnostics World::diagnostics() const {
  Diagnostics d;
  d.step = step_;
  d.t = t_;
  d.dt = dt_last_;
  const auto& m = p_[Field::Mass];
  for (std::size_t i = 0; i < p_.fluid(); ++i) {  // serial sums: identical for any thread count
    const Vec3 r = p_.pos(i), v = p_.vel(i);
    d.E_kin += 0.5 * m[i] * v.norm2();
    const Vec3 L = r.cross(v * m[i]);
    d.P[0] += m[i] * v.x; d.P[1] += m[i] * v.y; d.P[2] += m[i] * v.z;
    d.L[0] += L.x; d.L[1] += L.y; d.L[2] += L.z;
    d.v_max = std::max(d.v_max, v.norm());
  }
  const StageContext ctx = context();
  for (const auto& s : pipeline_->stages()) {
    d.E_int += s->internal_energy(ctx);
    d.E_pot += s->potential(ctx);
  }
  d.E_tot = d.E_kin + d.E_int + d.E_pot;
  const DensityStats& ds = stats_->density;
  d.h_iter_mean = ds.mean_iterations;
  d.h_iter_max = ds.max_iterations;
  d.h_not_converged = ds.not_converged;
  d.neighbours_mean = ds.mean_neighbours;
  d.correction_fallbacks = stats_->correction_fallbacks;
  return d;
}

std::vector<double> World::reference_values() const {
  if (!reference_) return {};
  return reference_->evaluate(p_, t_);
}

double World::reference_value(const std::string& name) const {
  const int k = find_column(ref_columns_, name);
  if (k < 0) throw std::out_of_range("scene " + cfg_.scene->name + " has no reference value '" + name + "'");
  return reference_values()[static_cast<std::size_t>(k)];
}

namespace {

/// Velocity component k of any particle, ghosts from their source (mirrored across walls).
double velocity_of(const Particles& p, std::size_t j, int k) {
  if (j < p.size()) return p.v[k][j];
  const std::size_t g = j - p.size();
  const double v = p.v[k][p.ghost_src[g]];
  return (p.ghost_flip[g] >> k) & 1u ? -v : v;
}

/// Vorticity dv_y/dx - dv_x/dy of the fluid (2D), from the standard SPH gradient
/// dv_k/dx_l ~ sum_b V_b (v_b - v_a)_k grad_l W_ab(h_a), over the last evaluation's neighbours (the
/// nearest periodic image of each: a particle may have wrapped since the lists were built).
std::vector<double> vorticity(const Particles& p, const Kernel& K, const NeighbourList& nl, const Domain& d) {
  const double Lx = d.bc[0] == Boundary::Periodic ? d.length(0) : 0.0;
  const double Ly = d.bc[1] == Boundary::Periodic ? d.length(1) : 0.0;
  std::vector<double> w(p.size(), 0.0);
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  const std::size_t n = std::min(p.fluid(), nl.offset.empty() ? 0 : nl.offset.size() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0.0;
    for (std::uint32_t j : nl.of(i)) {
      if (j == i || j >= p.total() || p.kind[j]) continue;
      double dx = p.x[0][i] - p.x[0][j], dy = p.x[1][i] - p.x[1][j];
      if (Lx > 0.0) dx -= Lx * std::nearbyint(dx / Lx);
      if (Ly > 0.0) dy -= Ly * std::nearbyint(dy / Ly);
      const double r = std::sqrt(dx * dx + dy * dy);
      if (r == 0.0 || r >= K.support() * h[i]) continue;
      const double f = m[j] / rho[j] * K.dWdr(r, h[i]) / r;  // grad W = f (dx, dy)
      s += (velocity_of(p, j, 1) - p.v[1][i]) * f * dx - (velocity_of(p, j, 0) - p.v[0][i]) * f * dy;
    }
    w[i] = s;
  }
  return w;
}

}  // namespace

Snapshot World::snapshot() const {
  Snapshot s;
  const std::size_t n = p_.size();
  s.scene = cfg_.scene->name;
  s.dim = p_.dim();
  s.step = step_;
  s.t = t_;
  s.dt = dt_last_;
  s.count = n;
  if (cfg_.params.physics.fpm != FpmType::None) s.points_label = "FPM points (u = v_x)";
  // entries in id order (by_id_): a particle keeps its place in every snapshot whatever the storage order
  s.x.resize(n); s.y.resize(n); s.z.resize(n); s.h.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = by_id_[k];
    s.x[k] = static_cast<float>(p_.x[0][i]);
    s.y[k] = static_cast<float>(p_.x[1][i]);
    s.z[k] = static_cast<float>(p_.x[2][i]);
    s.h[k] = static_cast<float>(p_[Field::H][i]);
  }
  const bool walls = p_.fluid() < n;
  if (walls) {
    s.kind.resize(n);
    for (std::size_t k = 0; k < n; ++k) s.kind[k] = p_.kind[by_id_[k]];
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
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = by_id_[k];
      const float v = static_cast<float>(value(i));
      f.values[k] = v;
      if (!std::isfinite(v) || p_.is_wall(i)) continue;  // the range is the fluid's
      if (first) { f.min = f.max = v; first = false; }
      f.min = std::min(f.min, v);
      f.max = std::max(f.max, v);
    }
    s.fields.push_back(std::move(f));
  };
  auto add_field = [&](Field fld) {
    const auto& a = p_[fld];
    add(std::string(info(fld).key), std::string(info(fld).label), [&](std::size_t i) { return a[i]; });
  };
  // the fields of earlier versions first, in their order; then the other display fields of the stages
  const Field first[] = {Field::Density, Field::Pressure, Field::Energy, Field::H, Field::SoundSpeed, Field::Neighbours,
                         Field::Omega};
  // point masses (pure N-body) have h = 0 everywhere: nothing to colour by, so h is left out
  const bool point_masses = !p_.has(Field::Density) && std::all_of(p_[Field::H].begin(), p_[Field::H].begin() +
                                                                   static_cast<std::ptrdiff_t>(n), [](double h) { return h == 0.0; });
  for (Field fld : first)
    if (p_.has(fld) && !(fld == Field::H && point_masses)) add_field(fld);
  for (std::size_t k = 0; k < kFieldCount; ++k) {
    const Field fld = static_cast<Field>(k);
    if (p_.has(fld) && info(fld).display && std::find(std::begin(first), std::end(first), fld) == std::end(first))
      add_field(fld);
  }
  add("speed", "speed |v|", [&](std::size_t i) { return p_.vel(i).norm(); });
  if (s.dim == 1) add("vx", "velocity v_x", [&](std::size_t i) { return p_.v[0][i]; });
  if (cfg_.params.physics.fpm != FpmType::None)  // Burgers' u first: what a viewer shows by default
    std::stable_partition(s.fields.begin(), s.fields.end(), [](const SnapshotField& f) { return f.name == "vx"; });
  if (s.dim == 2 && p_.has(Field::Density)) {
    const std::vector<double> w = vorticity(p_, kernel_, nl_, domain_);
    add("vorticity", "vorticity dv_y/dx - dv_x/dy", [&](std::size_t i) { return w[i]; });
  }
  if (walls) add("kind", "particle kind (0 fluid, 1 wall)", [&](std::size_t i) { return double(p_.kind[i]); });
  if (reference_) {
    ReferenceCurves c = reference_->curves(domain_, t_);
    s.exact = std::move(c.profiles);
    s.outlines = std::move(c.outlines);
  }
  return s;
}

}  // namespace sph

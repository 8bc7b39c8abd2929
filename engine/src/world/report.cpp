// Report: conserved quantities (seed 000 eqs. 3.4.1–3.4.5), the reference's values and
// curves, and snapshots with the scene's active fields.
#include <algorithm>
#include <cmath>

#include "core/pipeline.h"
#include "core/stage.h"
#include "sph/neighbour_cache.h"
#include "sph/report.h"

namespace sph {

StageContext Report::context() const {
  // as World hands the stages, for their energy sums (which only read the particles)
  const NeighbourList& lists = in_.lists.lists(in_.pipeline.exact_lists());
  return StageContext{in_.cfg.params, in_.kernel, in_.domain, const_cast<Particles&>(in_.p), lists, in_.lists.h_limit(),
                      in_.eta, in_.spacing, in_.wall_strength, in_.stats, in_.since};
}

const DensityStats& Report::density_stats() const { return in_.stats.density; }

std::vector<std::string> Report::stage_names() const {
  std::vector<std::string> out;
  for (const auto& s : in_.pipeline.stages()) out.emplace_back(s->name());
  return out;
}

Diagnostics Report::diagnostics() const {
  Diagnostics d;
  d.step = in_.step;
  d.t = in_.t;
  d.dt = in_.dt;
  const auto& m = in_.p[Field::Mass];
  for (std::size_t i = 0; i < in_.p.fluid(); ++i) {  // serial sums: identical for any thread count
    const Vec3 r = in_.p.pos(i), v = in_.p.vel(i);
    d.E_kin += 0.5 * m[i] * v.norm2();
    const Vec3 L = r.cross(v * m[i]);
    d.P[0] += m[i] * v.x; d.P[1] += m[i] * v.y; d.P[2] += m[i] * v.z;
    d.L[0] += L.x; d.L[1] += L.y; d.L[2] += L.z;
    d.v_max = std::max(d.v_max, v.norm());
  }
  const StageContext ctx = context();
  for (const auto& s : in_.pipeline.stages()) {
    d.E_int += s->internal_energy(ctx);
    d.E_pot += s->potential(ctx);
  }
  d.E_tot = d.E_kin + d.E_int + d.E_pot;
  const DensityStats& ds = in_.stats.density;
  d.h_iter_mean = ds.mean_iterations;
  d.h_iter_max = ds.max_iterations;
  d.h_not_converged = ds.not_converged;
  d.neighbours_mean = ds.mean_neighbours;
  d.correction_fallbacks = in_.stats.correction_fallbacks;
  d.updates = in_.updates;
  const ProjectionStats& ps = in_.stats.projection;
  d.dfsph_iter = ps.density_iterations;
  d.dfsph_div_iter = ps.divergence_iterations;
  d.dfsph_error = ps.density_error;
  d.dfsph_error_max = ps.density_error_max;
  return d;
}

std::vector<double> Report::reference_values() const {
  if (!in_.reference) return {};
  return in_.reference->evaluate(in_.p, in_.t);
}

double Report::reference_value(const std::string& name) const {
  const int k = find_column(in_.ref_columns, name);
  if (k < 0) throw std::out_of_range("scene " + in_.cfg.scene->name + " has no reference value '" + name + "'");
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

/// The real particle behind index j: itself, or a ghost's source.
std::size_t source_of(const Particles& p, std::size_t j) { return j < p.size() ? j : p.ghost_src[j - p.size()]; }

/// Vorticity dv_y/dx - dv_x/dy of the fluid (2D), from the standard SPH gradient
/// dv_k/dx_l ~ sum_b V_b (v_b - v_a)_k grad_l W_ab(h_a), over the last evaluation's neighbours (the
/// nearest periodic image of each: a particle may have wrapped since the lists were built). A ghost's
/// mass and density are its source's: the ghosts' copies are only as current as the last complete
/// evaluation, and a state saved from a run that stopped inside one (an h that outgrew every list
/// rebuild) holds new ghosts with no density yet, which made the vorticity NaN in a frame that loaded it.
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
      const std::size_t b = source_of(p, j);
      const double f = m[b] / rho[b] * K.dWdr(r, h[i]) / r;  // grad W = f (dx, dy)
      s += (velocity_of(p, j, 1) - p.v[1][i]) * f * dx - (velocity_of(p, j, 0) - p.v[0][i]) * f * dy;
    }
    w[i] = s;
  }
  return w;
}

}  // namespace

Snapshot Report::snapshot() const {
  Snapshot s;
  const std::size_t n = in_.p.size();
  s.scene = in_.cfg.scene->name;
  s.dim = in_.p.dim();
  s.step = in_.step;
  s.t = in_.t;
  s.dt = in_.dt;
  s.count = n;
  if (in_.cfg.params.physics.fpm != FpmType::None) s.points_label = "FPM points (u = v_x)";
  s.inset = in_.cfg.scene->inset;
  // entries in id order (in_.by_id): a particle keeps its place in every snapshot whatever the storage order
  s.x.resize(n); s.y.resize(n); s.z.resize(n); s.h.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = in_.by_id[k];
    s.x[k] = static_cast<float>(in_.p.x[0][i]);
    s.y[k] = static_cast<float>(in_.p.x[1][i]);
    s.z[k] = static_cast<float>(in_.p.x[2][i]);
    s.h[k] = static_cast<float>(in_.p[Field::H][i]);
  }
  const bool walls = in_.p.fluid() < n;
  if (walls) {
    s.kind.resize(n);
    for (std::size_t k = 0; k < n; ++k) s.kind[k] = in_.p.kind[in_.by_id[k]];
  }
  for (int k = 0; k < 3; ++k) {
    s.bounds[2 * k] = static_cast<float>(in_.domain.lo[k]);
    s.bounds[2 * k + 1] = static_cast<float>(in_.domain.hi[k]);
  }
  auto add = [&](std::string name, std::string label, auto&& value) {
    SnapshotField f;
    f.name = std::move(name);
    f.label = std::move(label);
    f.values.resize(n);
    bool first = true;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = in_.by_id[k];
      const float v = static_cast<float>(value(i));
      f.values[k] = v;
      if (!std::isfinite(v) || in_.p.is_wall(i)) continue;  // the range is the fluid's
      if (first) { f.min = f.max = v; first = false; }
      f.min = std::min(f.min, v);
      f.max = std::max(f.max, v);
    }
    s.fields.push_back(std::move(f));
  };
  auto add_field = [&](Field fld) {
    const auto& a = in_.p[fld];
    add(std::string(info(fld).key), std::string(info(fld).label), [&](std::size_t i) { return a[i]; });
  };
  // the fields of earlier versions first, in their order; then the other display fields of the stages
  const Field first[] = {Field::Density, Field::Pressure, Field::Energy, Field::H, Field::SoundSpeed, Field::Neighbours,
                         Field::Omega};
  // point masses (pure N-body) have h = 0 everywhere: nothing to colour by, so h is left out
  const auto& hs = in_.p[Field::H];
  const auto h_end = hs.begin() + static_cast<std::ptrdiff_t>(n);
  const bool point_masses = !in_.p.has(Field::Density) && std::all_of(hs.begin(), h_end, [](double h) { return h == 0.0; });
  for (Field fld : first)
    if (in_.p.has(fld) && !(fld == Field::H && point_masses)) add_field(fld);
  for (std::size_t k = 0; k < kFieldCount; ++k) {
    const Field fld = static_cast<Field>(k);
    if (in_.p.has(fld) && info(fld).display && std::find(std::begin(first), std::end(first), fld) == std::end(first))
      add_field(fld);
  }
  add("speed", "speed |v|", [&](std::size_t i) { return in_.p.vel(i).norm(); });
  if (s.dim == 1) add("vx", "velocity v_x", [&](std::size_t i) { return in_.p.v[0][i]; });
  if (in_.cfg.params.physics.fpm != FpmType::None)  // Burgers' u first: what a viewer shows by default
    std::stable_partition(s.fields.begin(), s.fields.end(), [](const SnapshotField& f) { return f.name == "vx"; });
  if (s.dim == 2 && in_.p.has(Field::Density)) {
    const std::vector<double> w = vorticity(in_.p, in_.kernel, in_.lists.every_list(), in_.domain);
    add("vorticity", "vorticity dv_y/dx - dv_x/dy", [&](std::size_t i) { return w[i]; });
  }
  if (walls) add("kind", "particle kind (0 fluid, 1 wall)", [&](std::size_t i) { return double(in_.p.kind[i]); });
  if (in_.reference) {
    ReferenceCurves c = in_.reference->curves(in_.domain, in_.t);
    s.exact = std::move(c.profiles);
    s.outlines = std::move(c.outlines);
  }
  return s;
}

}  // namespace sph

// Glass starts (see glass.h). The relaxation: unit density (m = 1/n), isothermal P = c^2 rho with c = 1,
// grad-h summation density with the quintic M6 kernel (no pairing instability at its default width;
// Price 2012, J. Comput. Phys. 231, 759, §2.8), the standard momentum equation, no viscosity, and the
// damping a = -v/tau (body_force_damping.cpp) of tau = 2 dx/c for 60 dx/c, dx = n^(-1/dim): a random
// start's density noise is then far below its initial tens of percent (glass_test.cpp measures it).
#include "glass.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

#include "scene_util.h"
#include "sph/world.h"

namespace sph::scenes {
namespace {

constexpr GlassRecipe kRecipe{};

double mean_spacing(int dim, std::size_t n) { return std::pow(static_cast<double>(n), -1.0 / dim); }

/// The relaxation run as a scene of its own (not in the built-in table): the random start in the
/// periodic unit box of `dim` axes.
SceneSpec relax_spec(int dim) {
  SceneSpec s;
  s.name = "glass_relaxation";
  s.category = "set-up";
  s.description = "random points relaxed to a glass by isothermal SPH pressure and damping";
  s.dim = dim;
  Params& d = s.defaults;
  d.kernel.type = KernelType::M6;
  d.physics.eos = EosType::Isothermal;
  d.physics.viscosity = ViscType::None;
  d.physics.energy = Toggle::Off;
  d.physics.body_force = BodyForce::Damping;
  d.gas.cs = 1.0;
  s.params = {{"n", 1000, 2, 1e8, true, "particles", "count"}, {"seed", 1, 0, 1e15, true, "random seed", "dimensionless"}};
  s.build = [dim](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n"));
    const std::vector<Vec3> x = glass_random_start(dim, n, static_cast<std::uint64_t>(v.at("seed")));
    Particles p = make_particles(prm, dim, n);
    const double dx = mean_spacing(dim, n), h = effective_eta(prm, dim) * dx;
    for (std::size_t i = 0; i < n; ++i) {
      p.x[0][i] = x[i].x;
      if (dim > 1) p.x[1][i] = x[i].y;
      if (dim > 2) p.x[2][i] = x[i].z;
      p[Field::Mass][i] = 1.0 / static_cast<double>(n);
      p[Field::H][i] = h;
    }
    SceneSetup out{std::move(p), {}, dx, 0.0};
    out.domain.lo = {0, 0, 0};
    out.domain.hi = {1, 1, 1};
    for (int k = 0; k < 3; ++k) out.domain.bc[k] = k < dim ? Boundary::Periodic : Boundary::Open;
    return out;
  };
  return s;
}

std::vector<Vec3> relax(int dim, std::size_t n, std::uint64_t seed) {
  const SceneSpec spec = relax_spec(dim);
  RunConfig cfg;
  cfg.scene = &spec;
  cfg.params = spec.defaults;
  cfg.values = {{"n", static_cast<double>(n)}, {"seed", static_cast<double>(seed)}};
  const double dx = mean_spacing(dim, n), t_end = kRecipe.t_relax * dx;
  cfg.params.body.tau = kRecipe.tau * dx;
  cfg.params.time.t_end = t_end;
  World w(cfg);
  w.advance_to(t_end);
  std::vector<Vec3> out;
  out.reserve(n);
  const Particles& p = w.particles();
  for (std::uint32_t i : w.by_id()) {
    Vec3 r = p.pos(i);
    for (double* c : {&r.x, &r.y, &r.z}) *c -= std::floor(*c);  // periodic wrap into [0,1)
    if (dim < 3) r.z = 0.0;
    if (dim < 2) r.y = 0.0;
    out.push_back(r);
  }
  return out;
}

}  // namespace

std::vector<Vec3> make_glass(int dim, std::size_t n, std::uint64_t seed) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("glass: dim must be 1, 2 or 3");
  if (n < 2) throw std::invalid_argument("glass: at least 2 particles");
  return relax(dim, n, seed);
}

std::vector<Vec3> glass_random_start(int dim, std::size_t n, std::uint64_t seed) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("glass: dim must be 1, 2 or 3");
  Random rng(seed);
  std::vector<Vec3> x(n);
  for (Vec3& r : x) {
    r.x = rng.uniform();
    if (dim > 1) r.y = rng.uniform();
    if (dim > 2) r.z = rng.uniform();
  }
  return x;
}

std::shared_ptr<const std::vector<Vec3>> glass(int dim, std::size_t n, std::uint64_t seed) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("glass: dim must be 1, 2 or 3");
  if (n < 2) throw std::invalid_argument("glass: at least 2 particles");
  using Key = std::tuple<int, std::size_t, std::uint64_t>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const std::vector<Vec3>>> memo;
  const Key key{dim, n, seed};
  const std::lock_guard<std::mutex> lock(mutex);  // held through a relaxation: each glass is built once
  if (auto it = memo.find(key); it != memo.end()) return it->second;
  // a few glasses stay (a session switches between scenes and resolutions); beyond that the smallest key goes
  if (memo.size() >= 8) memo.erase(memo.begin());
  auto g = std::make_shared<const std::vector<Vec3>>(make_glass(dim, n, seed));
  memo.emplace(key, g);
  return g;
}

std::vector<Vec3> glass_fill(int dim, const Vec3& lo, const Vec3& hi, double spacing, std::uint64_t seed,
                             std::size_t max_tile) {
  if (!(spacing > 0.0)) throw std::invalid_argument("glass_fill: spacing must be > 0");
  const double len[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
  // the tile's side: at most max_tile particles, at most the box's shortest side
  double side = spacing * std::pow(static_cast<double>(std::max<std::size_t>(max_tile, 2)), 1.0 / dim);
  for (int k = 0; k < dim; ++k) side = std::min(side, len[k]);
  std::size_t tiles[3] = {1, 1, 1};
  double tile_len[3] = {len[0], len[1], len[2]}, tile_volume = 1.0;
  for (int k = 0; k < dim; ++k) {
    tiles[k] = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(len[k] / side)));
    tile_len[k] = len[k] / static_cast<double>(tiles[k]);
    tile_volume *= tile_len[k];
  }
  const auto per_tile = std::max<std::size_t>(
      2, static_cast<std::size_t>(std::llround(tile_volume / std::pow(spacing, dim))));
  const auto g = glass(dim, per_tile, seed);
  std::vector<Vec3> out;
  out.reserve(per_tile * tiles[0] * tiles[1] * tiles[2]);
  for (std::size_t c = 0; c < tiles[2]; ++c)
    for (std::size_t b = 0; b < tiles[1]; ++b)
      for (std::size_t a = 0; a < tiles[0]; ++a)
        for (const Vec3& r : *g) {
          Vec3 q{lo.x + (static_cast<double>(a) + r.x) * tile_len[0], 0.0, 0.0};
          if (dim > 1) q.y = lo.y + (static_cast<double>(b) + r.y) * tile_len[1];
          if (dim > 2) q.z = lo.z + (static_cast<double>(c) + r.z) * tile_len[2];
          out.push_back(q);
        }
  return out;
}

}  // namespace sph::scenes

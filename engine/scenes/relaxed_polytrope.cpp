#include "relaxed_polytrope.h"

#include <mutex>
#include <tuple>
#include <utility>

#include "sph/world.h"

namespace sph::scenes {
namespace {

/// Everything the relaxed star depends on.
using Key =
    std::tuple<std::size_t, std::uint64_t, double, double, double, double, double, double, int, double, double, int>;

Key key_of(const Params& prm, std::size_t n, std::uint64_t seed, double t_relax) {
  return {n, seed, t_relax, prm.gas.gamma, prm.gas.K, prm.gravity.G, prm.gravity.theta, prm.gravity.tol,
          static_cast<int>(prm.kernel.type), prm.kernel.eta, prm.h.tol, prm.h.max_iter};
}

/// A few recent stars (a GUI session resets the same scene again and again; memory stays bounded).
constexpr std::size_t kMemo = 4;

std::shared_ptr<const RelaxedStar> relax(const Params& prm, std::size_t n, std::uint64_t seed, double t_relax) {
  RunConfig cfg = RunConfig::from_scene("polytrope");
  cfg.values["n"] = static_cast<double>(n);
  cfg.values["seed"] = static_cast<double>(seed);
  Params& q = cfg.params;
  q.kernel = prm.kernel;
  q.h = prm.h;
  q.gas.gamma = prm.gas.gamma;
  q.gas.K = prm.gas.K;
  q.gravity.G = prm.gravity.G;
  q.gravity.theta = prm.gravity.theta;
  q.gravity.tol = prm.gravity.tol;
  q.time.t_end = t_relax;
  World w(cfg);
  w.advance_to(t_relax);
  const Particles& p = w.particles();
  auto s = std::make_shared<RelaxedStar>();
  Vec3 c;
  double M = 0.0;
  for (std::uint32_t i : w.by_id()) {
    s->x.push_back(p.pos(i));
    s->m.push_back(p[Field::Mass][i]);
    s->h.push_back(p[Field::H][i]);
    s->rho.push_back(p[Field::Density][i]);
    c += p.pos(i) * p[Field::Mass][i];
    M += p[Field::Mass][i];
  }
  c = c * (1.0 / M);
  for (Vec3& x : s->x) x = x - c;
  return s;
}

}  // namespace

std::shared_ptr<const RelaxedStar> relaxed_polytrope(const Params& prm, std::size_t n, std::uint64_t seed,
                                                     double t_relax) {
  static std::mutex mutex;
  static std::vector<std::pair<Key, std::shared_ptr<const RelaxedStar>>> memo;
  const Key k = key_of(prm, n, seed, t_relax);
  const std::lock_guard<std::mutex> lock(mutex);  // held through a relaxation: the same star is built once
  for (const auto& [key, star] : memo)
    if (key == k) return star;
  auto star = relax(prm, n, seed, t_relax);
  if (memo.size() >= kMemo) memo.erase(memo.begin());
  memo.emplace_back(k, star);
  return star;
}

}  // namespace sph::scenes

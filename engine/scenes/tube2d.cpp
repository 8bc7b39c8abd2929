// Seed 000 §4.2: a 2D shock tube [0,5] x [0,1] with mirror walls (fictitious particles, §4.2.1):
// half the particles on a lattice in [0,1]^2, the other half on a lattice in [1,5] x [0,1];
// 512 particles, quintic kernel, v = 0, u = 0.05. The seed's gas is compressed 4:1 on the left.
// Artificial viscosity is on (seed 003 eq. 3.16): the tube drives a shock.
// Like the 1D tubes it takes rho, v, P on both sides (the defaults are the seed's: rho 1 | 0.25 and
// u = 0.05 at gamma = 1.4, so P = 0.02 | 0.005), with equal masses: the right lattice has the row count
// nearest to the density ratio, its column spacing makes the density exact, and the right wall moves
// by less than a spacing (never the density). With an ideal gas the exact Riemann solution along x is
// the reference until a wave reaches a wall.
#include <cmath>

#include "reference/riemann_reference.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "shared_setups.h"
#include "sph/riemann.h"

namespace sph::scenes {
namespace {

/// The light side's lattice: rows of spacing dy and columns of spacing dx, so that m = rho_r dx dy.
struct RightLattice {
  std::size_t rows, cols;
  double dx, dy, x_hi;
};

RightLattice right_lattice(const SceneValues& v) {
  const double n = v.at("n_side"), rl = v.at("rho_l"), rr = v.at("rho_r");
  const double m = rl / (n * n);
  RightLattice r{};
  r.rows = static_cast<std::size_t>(std::max(1LL, std::llround(n * std::sqrt(rr / rl))));
  r.dy = 1.0 / static_cast<double>(r.rows);
  r.dx = m / (rr * r.dy);
  r.cols = static_cast<std::size_t>(std::max(1LL, std::llround(4.0 / r.dx)));
  r.x_hi = 1.0 + static_cast<double>(r.cols) * r.dx;
  return r;
}

}  // namespace

SPH_SCENE(70, tube2d_scene) {
  SceneSpec s = tube_scene("tube2d",
                           "seed 000 §4.2: 2D tube [0,5]x[0,1], 4:1 compressed gas, mirror walls, 512 particles, quintic",
                           2, KernelType::M6, 20.0, 1.0, {"ideal_gas", "isothermal"});
  s.energy_bound = 1e-3;  // measured to t = 20: 1.6e-5 (leapfrog)
  s.error_bounds = {{"L1_rho", 0.021}};  // measured while the reference applies (to t = 5): 0.014
  s.assumptions = {resolution("scene.n_side", 16, 2000)};
  s.params = {{"n_side", 16, 2, 2000, true, "lattice particles per unit length on the dense side (seed: 16)", "particles per length"}};
  // the seed's gas: 4:1 compressed on the left, u = 0.05 at gamma 1.4 on both sides
  for (SceneParam& q : tube_state_params({1.0, 0.0, 0.02}, {0.25, 0.0, 0.005}, "mass/area")) s.params.push_back(std::move(q));
  s.build = [s](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n_side"));  // dense block: n x n in [0,1]^2
    const RightLattice r = right_lattice(v);
    const std::size_t count = n * n + r.rows * r.cols;
    Particles p = make_particles(prm, s.dim, count);
    const double dxl = 1.0 / n, eta = effective_eta(prm, 2), g = prm.gas.gamma;
    const double m = v.at("rho_l") / static_cast<double>(n * n);
    std::size_t k = 0;
    auto put = [&](double x, double y, double dx, bool left) {
      p.x[0][k] = x;
      p.x[1][k] = y;
      p.v[0][k] = left ? v.at("v_l") : v.at("v_r");
      p[Field::Mass][k] = m;
      p[Field::H][k] = eta * dx;
      if (p.has(Field::Energy))
        p[Field::Energy][k] = left ? energy_from_pressure(v.at("p_l"), v.at("rho_l"), g)
                                   : energy_from_pressure(v.at("p_r"), v.at("rho_r"), g);
      ++k;
    };
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) put((i + 0.5) * dxl, (j + 0.5) * dxl, dxl, true);
    for (std::size_t j = 0; j < r.rows; ++j)
      for (std::size_t i = 0; i < r.cols; ++i) put(1.0 + (i + 0.5) * r.dx, (j + 0.5) * r.dy, std::sqrt(r.dx * r.dy), false);
    SceneSetup out{std::move(p), {}, dxl, 0.0};
    out.domain.lo = {0, 0, 0};
    out.domain.hi = {r.x_hi, 1, 1};
    out.domain.bc = {Boundary::Wall, Boundary::Wall, Boundary::Open};
    return out;
  };
  s.initial_pressure = [](const Vec3& x, const SceneValues& v) { return x.x < 1.0 ? v.at("p_l") : v.at("p_r"); };
  s.reference = [](const Params& p, const SceneValues& v) -> std::unique_ptr<Reference> {
    if (p.physics.eos != EosType::IdealGas) return nullptr;  // the Riemann solution is an ideal gas's
    const auto [left, right] = tube_states(v);
    return make_riemann_reference(left, right, p.gas.gamma, 1.0, 0.0, right_lattice(v).x_hi);
  };
  return s;
}

}  // namespace sph::scenes

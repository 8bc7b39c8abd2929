// Seed 000 §4.2: a 2D shock tube [0,5] x [0,1] with mirror walls (fictitious particles, §4.2.1):
// half the particles on a lattice in [0,1]^2, the other half on a lattice in [1,5] x [0,1];
// 512 particles, quintic kernel, v = 0, u = 0.05. The seed's gas is compressed 4:1 on the left.
// Artificial viscosity is on (seed 003 eq. 3.16): the tube drives a shock.
#include <cmath>

#include "families.h"
#include "scene_util.h"

namespace sph::scenes {

SceneSpec tube2d_scene() {
  SceneSpec s;
  s.name = "tube2d";
  s.category = "gas dynamics / shock tubes";
  s.description = "seed 000 §4.2: 2D tube [0,5]x[0,1], 4:1 compressed gas, mirror walls, 512 particles, quintic";
  s.dim = 2;
  s.defaults.kernel.type = KernelType::M6;
  s.defaults.time.t_end = 20.0;
  s.defaults.time.dt_out = 1.0;
  s.allow(Slot::Eos, {"ideal_gas", "isothermal"});
  s.allow(Slot::Walls, {"none"});
  s.energy_bound = 1e-3;  // measured to t = 20: 1.6e-5 (leapfrog)
  s.params = {{"n_side", 16, 2, 2000, true, "lattice particles per unit length on the dense side (seed: 16)", "particles per length"},
              {"u0", 0.05, 1e-12, 1e12, false, "initial specific internal energy (seed 000: 0.05)", "energy/mass"}};
  s.build = [s](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n_side"));  // dense block: n x n in [0,1]^2
    const std::size_t nr = n / 2;                               // light block: spacing 2/n
    const std::size_t count = n * n + (4 * nr) * nr;
    Particles p = make_particles(prm, s.dim, count);
    const double dxl = 1.0 / n, dxr = 1.0 / nr, eta = effective_eta(prm, 2);
    const double m = 1.0 / static_cast<double>(n * n);  // dense side density 1
    std::size_t k = 0;
    auto put = [&](double x, double y, double dx) {
      p.x[0][k] = x;
      p.x[1][k] = y;
      p[Field::Mass][k] = m;
      p[Field::H][k] = eta * dx;
      if (p.has(Field::Energy)) p[Field::Energy][k] = v.at("u0");
      ++k;
    };
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) put((i + 0.5) * dxl, (j + 0.5) * dxl, dxl);
    for (std::size_t j = 0; j < nr; ++j)
      for (std::size_t i = 0; i < 4 * nr; ++i) put(1.0 + (i + 0.5) * dxr, (j + 0.5) * dxr, dxr);
    SceneSetup out{std::move(p), {}, dxl, 0.0};
    out.domain.lo = {0, 0, 0};
    out.domain.hi = {5, 1, 1};
    out.domain.bc = {Boundary::Wall, Boundary::Wall, Boundary::Open};
    return out;
  };
  return s;
}

}  // namespace sph::scenes

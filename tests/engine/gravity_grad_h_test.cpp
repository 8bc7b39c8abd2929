// The grad-h term of kernel-softened gravity (physics/gravity_grad_h.cpp): the acceleration it completes
// is minus the gradient of the potential energy with every h re-solved, so the rate of work
// -sum_a m_a v_a . a_a equals dE_pot/dt along any velocity field. Checked by central differences of
// E_pot(x + d v) on a centrally condensed blob, where h varies by a factor of about 3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "stage_test_util.h"

namespace sph {
namespace {

/// splitmix64 in [0, 1) (deterministic)
double uniform(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

struct Blob {
  test::StageBench b;
  std::array<std::vector<double>, 3> x0, v;

  explicit Blob(Softening s, std::size_t n) : b(params(s), 3, n, test::pipeline_fields(params(s), 3)) {
    std::uint64_t seed = 7;
    for (int k = 0; k < 3; ++k) { x0[k].resize(n); v[k].resize(n); }
    for (std::size_t i = 0; i < n; ++i) {
      double d[3], r2;
      do {  // a direction in the unit ball
        for (double& c : d) c = 2.0 * uniform(seed) - 1.0;
        r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      } while (r2 > 1.0 || r2 < 1e-4);
      const double r = uniform(seed), scale = r / std::sqrt(r2);  // uniform in r: rho ~ 1/r^2
      for (int k = 0; k < 3; ++k) {
        x0[k][i] = d[k] * scale;
        v[k][i] = uniform(seed) - 0.5;
      }
      b.p[Field::Mass][i] = 1.0 / static_cast<double>(n);
      b.p[Field::H][i] = 0.3;
    }
  }
  static Params params(Softening s) {
    Params prm;
    Physics& ph = prm.physics;
    ph.density = DensityMode::Summation;
    ph.smoothing = HMode::Variable;
    ph.eos = EosType::None;
    ph.force = ForceType::None;
    ph.viscosity = ViscType::None;
    ph.energy = Toggle::Off;
    ph.gravity = GravityType::Direct;
    prm.gravity.softening = s;
    prm.h.tol = 1e-13;
    return prm;
  }
  /// Places the particles at x0 + d v and runs the pipeline (h solved, gravity and its grad-h term);
  /// returns E_pot = 1/2 sum m phi.
  double evaluate(double d) {
    Particles& p = b.p;
    const std::size_t n = p.fluid();
    for (int k = 0; k < 3; ++k)
      for (std::size_t i = 0; i < n; ++i) {
        p.x[k][i] = x0[k][i] + d * v[k][i];
        p.v[k][i] = v[k][i];
      }
    Pipeline pl(b.prm, 3);
    for (int attempt = 0; attempt < 10; ++attempt) {  // new lists while an h outgrows them
      b.prepare(FieldSet{});
      for (auto& a : p.a) std::fill(a.begin(), a.end(), 0.0);
      bool done = true;
      for (const auto& s : pl.stages())
        if (!b.run(*s)) { done = false; break; }
      if (done) break;
    }
    double e = 0.0;
    for (std::size_t i = 0; i < n; ++i) e += 0.5 * p[Field::Mass][i] * p[Field::Potential][i];
    return e;
  }
  /// |dE_pot/dt + sum m v . a| relative to sum m |v| |a|, dE_pot/dt by central differences of step d.
  double work_mismatch(double d) {
    const double de = (evaluate(d) - evaluate(-d)) / (2.0 * d);
    evaluate(0.0);
    const Particles& p = b.p;
    double work = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      double va = 0.0, v2 = 0.0, a2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        va += v[k][i] * p.a[k][i];
        v2 += v[k][i] * v[k][i];
        a2 += p.a[k][i] * p.a[k][i];
      }
      work += p[Field::Mass][i] * va;
      scale += p[Field::Mass][i] * std::sqrt(v2 * a2);
    }
    return std::abs(de + work) / scale;
  }
};

TEST(GravityGradH, ForceIsMinusTheGradientOfThePotentialEnergyWithHResolved) {
  Blob with(Softening::Kernel, 400), without(Softening::KernelNoGradH, 400);
  const double err_with = with.work_mismatch(1e-5), err_without = without.work_mismatch(1e-5);
  double hmin = 1e9, hmax = 0.0;
  for (std::size_t i = 0; i < with.b.p.fluid(); ++i) {
    hmin = std::min(hmin, with.b.p[Field::H][i]);
    hmax = std::max(hmax, with.b.p[Field::H][i]);
  }
  std::printf("400 particles, h in [%.3f, %.3f]: |dE_pot/dt + sum m v.a| / sum m |v||a| = %.2e with the grad-h "
              "term, %.2e without\n",
              hmin, hmax, err_with, err_without);
  EXPECT_GT(hmax / hmin, 2.0);  // h varies: the term matters
  EXPECT_LT(err_with, 1e-6);
  EXPECT_GT(err_without, 1e-3);  // the test can tell the term's absence
}

TEST(GravityGradH, StagesRunOnlyForKernelSofteningOfASolvedH) {
  auto names = [](const Params& prm) {
    std::string s;
    const Pipeline pl(prm, 3);
    for (const auto& st : pl.stages()) s += std::string(st->name()) + ";";
    return s;
  };
  Params prm = Blob::params(Softening::Kernel);
  EXPECT_NE(names(prm).find("gravity grad-h: force"), std::string::npos);
  prm.gravity.softening = Softening::Plummer;
  EXPECT_EQ(names(prm).find("grad-h"), std::string::npos);
  prm.gravity.softening = Softening::KernelNoGradH;
  EXPECT_EQ(names(prm).find("grad-h"), std::string::npos);
  prm.gravity.softening = Softening::Kernel;
  prm.physics.smoothing = HMode::Fixed;  // h does not follow rho: no term
  EXPECT_EQ(names(prm).find("grad-h"), std::string::npos);
}

}  // namespace
}  // namespace sph

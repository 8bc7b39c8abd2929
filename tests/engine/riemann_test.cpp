// Physics checks of the exact Riemann solver (seed 003 eqs. 3.20-3.51; Toro ch. 4, table 4.2).
#include "sph/riemann.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sph {
namespace {

constexpr double kGamma = 1.4;
const GasState kSodL{1.0, 0.0, 1.0}, kSodR{0.125, 0.0, 0.1};

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
double sound(const GasState& s, double g) { return std::sqrt(g * s.p / s.rho); }

// Independent one-wave pressure function f_K(p) (Toro 4.2), for residual checks.
double wave_f(double p, const GasState& k, double g) {
  const double c = sound(k, g);
  if (p <= k.p) return 2.0 * c / (g - 1.0) * (std::pow(p / k.p, (g - 1.0) / (2.0 * g)) - 1.0);
  const double a = 2.0 / ((g + 1.0) * k.rho), b = (g - 1.0) / (g + 1.0) * k.p;
  return (p - k.p) * std::sqrt(a / (p + b));
}

bool same_state(const GasState& a, const GasState& b) {
  return a.rho == b.rho && a.v == b.v && a.p == b.p;
}

TEST(Riemann, SodStarStateMatchesToroTable) {
  const RiemannSolver rs(kSodL, kSodR, kGamma);
  const RiemannStar st = rs.star();
  // Computed: p* = 0.303130178..., u* = 0.927452620...
  EXPECT_LT(rel(st.p, 0.30313), 1e-5);
  EXPECT_LT(rel(st.v, 0.92745), 1e-5);
  EXPECT_GT(st.iterations, 0);
  EXPECT_NEAR(wave_f(st.p, kSodL, kGamma) + wave_f(st.p, kSodR, kGamma), 0.0, 1e-15);
  const double t = 0.25;
  const double x_contact = st.v * t;
  // Star-left (behind the fan) and post-shock (between contact and shock) densities.
  EXPECT_NEAR(rs.sample(x_contact - 1e-3, t).rho, 0.42632, 1e-4);
  EXPECT_NEAR(rs.sample(x_contact + 1e-3, t).rho, 0.26557, 1e-4);
  EXPECT_DOUBLE_EQ(rs.gamma(), kGamma);
  EXPECT_DOUBLE_EQ(rs.internal_energy(-10.0, t), 1.0 / (0.4 * 1.0));
}

TEST(Riemann, TimeZeroIsTheInitialDiscontinuity) {
  const RiemannSolver rs(kSodL, kSodR, kGamma, 0.5);
  EXPECT_TRUE(same_state(rs.sample(0.4999, 0.0), kSodL));
  EXPECT_TRUE(same_state(rs.sample(0.5001, 0.0), kSodR));
  EXPECT_THROW(rs.sample(0.5, -1.0), std::invalid_argument);
}

TEST(Riemann, RankineHugoniotAcrossSampledShock) {
  const RiemannSolver rs(kSodL, kSodR, kGamma);
  const double t = 0.2, g = kGamma;
  // Locate the shock by bisection on the sampled density between contact and far right.
  double a = rs.star().v * t + 1e-6, b = 1.0;
  const GasState pre = rs.sample(b, t), post = rs.sample(a, t);
  ASSERT_TRUE(same_state(pre, kSodR));
  for (int i = 0; i < 200 && b - a > 0.0; ++i) {
    const double m = 0.5 * (a + b);
    if (m == a || m == b) break;
    (same_state(rs.sample(m, t), kSodR) ? b : a) = m;
  }
  const double s = b / t;  // shock speed from the sampled shock position
  // Fluxes in the shock frame, w = v - S: mass, momentum, total enthalpy flux.
  auto mass = [&](const GasState& q) { return q.rho * (q.v - s); };
  auto mom = [&](const GasState& q) { return q.rho * (q.v - s) * (q.v - s) + q.p; };
  auto energy = [&](const GasState& q) {
    const double w = q.v - s;
    return q.rho * w * (g * q.p / ((g - 1.0) * q.rho) + 0.5 * w * w);
  };
  EXPECT_LT(rel(mass(post), mass(pre)), 1e-10);
  EXPECT_LT(rel(mom(post), mom(pre)), 1e-10);
  EXPECT_LT(rel(energy(post), energy(pre)), 1e-10);
  EXPECT_GT(post.p, pre.p);  // compressive: entropy increases across the shock
  EXPECT_GT(post.p / std::pow(post.rho, g), pre.p / std::pow(pre.rho, g));
}

TEST(Riemann, RarefactionFanIsIsentropicWithConstantInvariant) {
  // Sod, and Toro's modified Sod (v_L = 0.75) whose left fan is transonic and moving.
  for (const GasState left : {kSodL, GasState{1.0, 0.75, 1.0}}) {
    const RiemannSolver rs(left, kSodR, kGamma);
    const double t = 0.3, g = kGamma;
    const GasState star_left = rs.sample(rs.star().v * t - 1e-9, t);
    const double head = (left.v - sound(left, g)) * t;
    const double tail = (rs.star().v - sound(star_left, g)) * t;
    const double entropy = left.p / std::pow(left.rho, g);
    const double invariant = left.v + 2.0 * sound(left, g) / (g - 1.0);
    EXPECT_LT(rel(star_left.p / std::pow(star_left.rho, g), entropy), 1e-12);
    for (int i = 1; i <= 9; ++i) {
      const double x = head + (tail - head) * i / 10.0;
      const GasState q = rs.sample(x, t);
      ASSERT_LT(q.rho, left.rho);  // inside the fan, not a constant state
      ASSERT_GT(q.rho, star_left.rho);
      EXPECT_LT(rel(q.p / std::pow(q.rho, g), entropy), 1e-12) << "x=" << x;
      EXPECT_LT(rel(q.v + 2.0 * sound(q, g) / (g - 1.0), invariant), 1e-12) << "x=" << x;
      EXPECT_NEAR(q.v - sound(q, g), x / t, 1e-12) << "x=" << x;  // fan of C- characteristics
    }
  }
}

TEST(Riemann, Toro123Problem) {
  const RiemannSolver rs({1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, kGamma);
  // Table 4.2 prints p* = 0.00189 (3 significant figures): compare to half a unit in the last
  // place; two symmetric fans have the closed form p* = p (1 - (g-1)/2 * 2/(2c))^(2g/(g-1)).
  const double c = std::sqrt(kGamma * 0.4);
  const double exact = 0.4 * std::pow(1.0 - 0.4 * 2.0 / (2.0 * c), 2.0 * kGamma / 0.4);
  EXPECT_NEAR(rs.star().p, 0.00189, 5e-6);
  EXPECT_LT(rel(rs.star().p, exact), 1e-12);  // computed p* = 0.0018938734...
  EXPECT_NEAR(rs.star().v, 0.0, 1e-14);
}

TEST(Riemann, ToroTest3StrongShock) {
  const RiemannSolver rs({1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, kGamma);
  EXPECT_LT(rel(rs.star().p, 460.894), 1e-4);
  EXPECT_LT(rel(rs.star().v, 19.5975), 1e-4);
}

TEST(Riemann, ColdCollisionApproachesStrongShockLimit) {
  // Noh-like collision of cold gas, gamma 5/3: two strong shocks, p* -> (g+1)/2 rho v^2 = 4/3,
  // compression (g+1)/(g-1) = 4 (exercises the two-shock guess and the bracketed Newton).
  const RiemannSolver rs({1.0, 1.0, 1e-10}, {1.0, -1.0, 1e-10}, 5.0 / 3.0);
  EXPECT_NEAR(rs.star().p, 4.0 / 3.0, 1e-6);
  EXPECT_NEAR(rs.star().v, 0.0, 1e-14);
  EXPECT_NEAR(rs.sample(0.0, 1.0).rho, 4.0, 1e-6);
  EXPECT_LT(rs.star().iterations, 20);
}

TEST(Riemann, MirroredProblemGivesMirroredSolution) {
  const GasState l{1.0, 0.3, 1000.0}, r{0.2, -0.5, 0.01};
  const RiemannSolver rs(l, r, kGamma);
  const RiemannSolver mirror({r.rho, -r.v, r.p}, {l.rho, -l.v, l.p}, kGamma);
  EXPECT_LT(rel(mirror.star().p, rs.star().p), 1e-13);
  EXPECT_LT(std::abs(mirror.star().v + rs.star().v), 1e-12 * std::abs(rs.star().v));
  const double t = 0.01;
  for (int i = -50; i <= 50; ++i) {
    const double x = 0.0123 * i + 1e-7;  // avoid landing exactly on a wave edge
    const GasState a = rs.sample(x, t), b = mirror.sample(-x, t);
    EXPECT_LT(rel(b.rho, a.rho), 1e-11) << "x=" << x;
    EXPECT_LT(rel(b.p, a.p), 1e-11) << "x=" << x;
    EXPECT_NEAR(b.v, -a.v, 1e-11 * (1.0 + std::abs(a.v))) << "x=" << x;
  }
}

TEST(Riemann, Seed003TubeSatisfiesPressureFunction) {
  const GasState l{1.0, 0.0, 1.0}, r{0.25, 0.0, 0.1795};
  const RiemannSolver rs(l, r, kGamma);
  const double p = rs.star().p;
  // Computed: p* = 0.429346119662815, u* = 0.673102732054300 in 4 Newton iterations
  // (left rarefaction, right shock); star densities 0.546663 (left) and 0.457328 (right).
  const double fl = wave_f(p, l, kGamma), fr = wave_f(p, r, kGamma);
  EXPECT_NEAR(fl + fr + (r.v - l.v), 0.0, 1e-14);
  EXPECT_LT(rel(rs.star().v, 0.5 * (l.v + r.v) + 0.5 * (fr - fl)), 1e-13);
  EXPECT_NEAR(p, 0.429346119662815, 1e-12);
  EXPECT_NEAR(rs.star().v, 0.673102732054300, 1e-12);
  EXPECT_LT(p, l.p);
  EXPECT_GT(p, r.p);
}

TEST(Riemann, WaveSpanBoundsTheFan) {
  // Sod: the left rarefaction's head moves at -c_L = -sqrt(1.4); the shock at 1.7522 (Toro §4.3.3,
  // Table 4.3's shock position at t = 0.25 is 0.5 + 0.25 S). Outside the span the initial states hold.
  const RiemannSolver sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const WaveSpan w = sod.span();
  EXPECT_NEAR(w.s_min, -std::sqrt(1.4), 1e-12);
  EXPECT_NEAR(w.s_max, 1.7522, 1e-4);
  const double t = 0.2, eps = 1e-9;
  EXPECT_EQ(sod.sample(w.s_min * t - eps, t).p, 1.0);
  EXPECT_LT(sod.sample(w.s_min * t + 1e-4, t).p, 1.0);
  EXPECT_EQ(sod.sample(w.s_max * t + eps, t).p, 0.1);
  EXPECT_GT(sod.sample(w.s_max * t - eps, t).p, 0.1);
  // a right-moving shock and a right rarefaction (Toro test 4 mirrored): the span's edges are the
  // outermost wave speeds whatever their kind
  const RiemannSolver t4({1.0, 0.0, 0.01}, {1.0, 0.0, 100.0}, 1.4);
  const WaveSpan w4 = t4.span();
  EXPECT_LT(w4.s_min, 0.0);
  EXPECT_NEAR(w4.s_max, std::sqrt(140.0), 1e-9);  // the right fan's head: c_R = sqrt(1.4 * 100)
}

TEST(Riemann, BadInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RiemannSolver({0.0, 0.0, 1.0}, kSodR, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannSolver(kSodL, {0.125, 0.0, -0.1}, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannSolver(kSodL, {nan, 0.0, 0.1}, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannSolver(kSodL, kSodR, 1.0), std::invalid_argument);
  EXPECT_THROW(RiemannSolver(kSodL, kSodR, 0.5), std::invalid_argument);
  // Strongly diverging flow: 2(cL + cR)/(gamma - 1) < vR - vL opens a vacuum.
  EXPECT_THROW(RiemannSolver({1.0, -10.0, 1.0}, {1.0, 10.0, 1.0}, kGamma), std::invalid_argument);
}

}  // namespace
}  // namespace sph

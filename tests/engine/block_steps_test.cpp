// BlockSteps, individual time steps on a power-of-two hierarchy, driven by hand-made rates:
// - under a constant acceleration per particle, kick-drift-kick is exact whatever each particle's
//   step, so every particle lands on x0 + v0 t + a t^2 / 2 (and u on u0 + r t) to rounding, while the
//   particles take the levels their wanted dt give (a 1000:1 range over 11 levels);
// - harmonic oscillators of different frequencies each keep leapfrog's energy error of their own step
//   (|dE/E| about (omega dt)^2 / 4 with omega dt in [cfl/2, cfl] over 20 periods), not of the shortest;
// - on a chain of neighbours, no step is more than four times its neighbours' shortest (Saitoh &
//   Makino 2009), and the neighbours of a particle that suddenly wants a short step are woken one ring
//   a sub-step.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "integrators/block_steps.h"

namespace sph {
namespace {

/// n particles in 1D with an evolved scalar u and its rate; no walls, no ghosts.
struct Line {
  Particles p;
  std::vector<double> u, du;
  PhaseSpace s;
  explicit Line(std::size_t n) : p(1, n, FieldSet{}), u(n, 0.0), du(n, 0.0) {
    s.dim = 1;
    s.n = n;
    for (int k = 0; k < 3; ++k) { s.x[k] = &p.x[k]; s.v[k] = &p.v[k]; s.a[k] = &p.a[k]; }
    s.evolved.push_back({&u, &du});
  }
};

/// Lists where particle i's neighbours are i-1, i, i+1 (a chain), or none at all.
NeighbourList chain(std::size_t n, bool linked) {
  NeighbourList nl;
  nl.offset.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    if (linked) {
      if (i > 0) nl.index.push_back(static_cast<std::uint32_t>(i - 1));
      nl.index.push_back(static_cast<std::uint32_t>(i));
      if (i + 1 < n) nl.index.push_back(static_cast<std::uint32_t>(i + 1));
    }
    nl.offset.push_back(static_cast<std::uint32_t>(nl.index.size()));
  }
  return nl;
}

TEST(BlockSteps, ConstantAccelerationIsExactOnEveryLevel) {
  const std::size_t n = 12;
  Line L(n);
  std::vector<double> g(n), r(n), want(n);
  for (std::size_t i = 0; i < n; ++i) {
    L.p.x[0][i] = 0.1 * static_cast<double>(i);
    L.p.v[0][i] = 1.0 - 0.2 * static_cast<double>(i);
    g[i] = std::pow(-1.0, static_cast<double>(i)) * (1.0 + static_cast<double>(i));
    r[i] = 0.5 * static_cast<double>(i);
    want[i] = 1e-3 * std::pow(2.0, static_cast<double>(i) * 10.0 / static_cast<double>(n - 1));  // 1e-3 .. 1
    L.p.a[0][i] = g[i];
    L.du[i] = r[i];
  }
  const std::vector<double> x0 = L.p.x[0], v0 = L.p.v[0];
  const NeighbourList nl = chain(n, false);
  BlockSteps b(11);
  int evaluations = 0;
  const BlockSteps::Hooks hooks{[&](double) {
                                  ++evaluations;
                                  for (std::uint32_t i : b.active()) { L.p.a[0][i] = g[i]; L.du[i] = r[i]; }
                                },
                                [&](std::vector<double>& w) { w = want; },
                                [&]() -> const NeighbourList& { return nl; }};
  double t = 0.0;
  std::vector<std::int64_t> first_lengths;
  while (t < 3.0 - 1e-12) {
    t += b.step(L.s, L.p, hooks, 3.0 - t);
    if (first_lengths.empty()) first_lengths = b.lengths();
  }
  ASSERT_TRUE(b.synchronised());
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(L.p.x[0][i], x0[i] + v0[i] * t + 0.5 * g[i] * t * t, 1e-11) << i;
    EXPECT_NEAR(L.p.v[0][i], v0[i] + g[i] * t, 1e-11) << i;
    EXPECT_NEAR(L.u[i], r[i] * t, 1e-11) << i;
  }
  // levels: particle 0 on the shortest step, the last on the block (1024 times longer), each within
  // a factor two below its wanted dt
  EXPECT_EQ(first_lengths.front(), 1);
  EXPECT_EQ(first_lengths.back(), 1024);
  EXPECT_LT(evaluations, 3 * 1000 * 12 / 4);  // far fewer particle updates than all on the shortest
}

TEST(BlockSteps, EachOscillatorKeepsTheErrorOfItsOwnStep) {
  // leapfrog's energy error for x'' = -omega^2 x oscillates with relative amplitude (omega dt)^2 / 4: each
  // oscillator shows that of its own level (omega dt between cfl/2 and cfl), 16^2 times larger for the
  // slowest than if it took the fastest one's step
  const std::size_t n = 3;
  Line L(n);
  std::vector<double> w2(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double omega = std::pow(4.0, static_cast<double>(i));  // 1, 4, 16
    w2[i] = omega * omega;
    L.p.x[0][i] = 1.0;
    L.p.a[0][i] = -w2[i];
  }
  const NeighbourList nl = chain(n, false);
  BlockSteps b(8);
  const double cfl = 0.05;
  const BlockSteps::Hooks hooks{[&](double) { for (std::uint32_t i : b.active()) L.p.a[0][i] = -w2[i] * L.p.x[0][i]; },
                                [&](std::vector<double>& w) {
                                  w.resize(n);
                                  for (std::size_t i = 0; i < n; ++i) w[i] = cfl / std::sqrt(w2[i]);
                                },
                                [&]() -> const NeighbourList& { return nl; }};
  const double t_end = 2.0 * M_PI * 20.0;  // 20 periods of the slowest
  double t = 0.0;
  std::vector<double> worst(n, 0.0);
  while (t < t_end - 1e-12) {
    t += b.step(L.s, L.p, hooks, t_end - t);
    if (!b.synchronised()) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const double E = 0.5 * L.p.v[0][i] * L.p.v[0][i] + 0.5 * w2[i] * L.p.x[0][i] * L.p.x[0][i];
      worst[i] = std::max(worst[i], std::abs(E / (0.5 * w2[i]) - 1.0));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_LE(worst[i], 1.05 * 0.25 * cfl * cfl) << i;
    EXPECT_GE(worst[i], 0.9 * 0.25 * 0.25 * cfl * cfl) << i;
  }
}

TEST(BlockSteps, NeighboursStayWithinTwoLevelsAndAreWoken) {
  const std::size_t n = 40;
  Line L(n);
  const NeighbourList nl = chain(n, true);
  std::vector<double> want(n, 1.0);
  want[0] = 1.0 / 1024.0;
  want[30] = 16.0 / 1024.0;
  BlockSteps b(11);
  const BlockSteps::Hooks hooks{[&](double) {}, [&](std::vector<double>& w) { w = want; },
                                [&]() -> const NeighbourList& { return nl; }};
  auto limited = [&] {  // on the levels (a step may be shorter: it starts on a multiple of itself)
    const auto& len = b.levels();
    for (std::size_t i = 0; i + 1 < n; ++i)
      if (len[i] > 4 * len[i + 1] || len[i + 1] > 4 * len[i]) return false;
    return true;
  };
  b.step(L.s, L.p, hooks, 10.0);  // the block (1 time unit, 1024 ticks) and its first sub-step
  EXPECT_TRUE(limited());
  const std::vector<std::int64_t> first = b.lengths();
  EXPECT_EQ(first[0], 1);
  EXPECT_EQ(first[1], 4);
  EXPECT_EQ(first[2], 16);
  EXPECT_EQ(first[n / 2], 1024);
  EXPECT_EQ(first[30], 16);
  EXPECT_EQ(first[29], 64);
  EXPECT_EQ(first[28], 256);
  // at its step's end (tick 16) particle 30 wants the shortest step: its neighbours, 64 and 256 ticks
  // long, are woken one sub-step later each instead of running on to their steps' ends
  want[30] = 1.0 / 1024.0;
  std::int64_t sub_steps = 1, woken29 = -1, woken28 = -1;
  while (!b.synchronised()) {
    b.step(L.s, L.p, hooks, 10.0);
    ++sub_steps;
    // the limit holds but while the wake spreads out from particle 30, one ring a sub-step, to the
    // fifth ring (level 4^5 = 1024)
    if (sub_steps < 16 || sub_steps >= 21) {
      EXPECT_TRUE(limited()) << "after sub-step " << sub_steps;
    }
    if (woken29 < 0 && b.lengths()[29] <= 4) woken29 = sub_steps;
    if (woken28 < 0 && b.lengths()[28] <= 16) woken28 = sub_steps;
  }
  EXPECT_EQ(sub_steps, 1024);  // particle 0 sets the sub-steps: one tick each
  EXPECT_EQ(woken29, 17);
  EXPECT_EQ(woken28, 18);
  // the wake stops where the levels allow the long step again: particles 24 and below ran the block
  EXPECT_EQ(b.starts()[24], 0);
  EXPECT_EQ(b.starts()[20], 0);
  EXPECT_EQ(b.lengths()[20], 1024);
}

}  // namespace
}  // namespace sph

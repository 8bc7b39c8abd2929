// Orbit trails (sph/trail_log.h): sampled every step, a Kepler orbit's trail is one closed line on the
// exact ellipse (it was nine dashes when sampled at the frames drawn), for e = 0 and e = 0.5; the scene's
// reference draws that ellipse.
#include "sph/trail_log.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <numbers>
#include <thread>

#include "sph/stepper.h"
#include "sph/world.h"

namespace sph {
namespace {

struct Orbit {
  double worst = 0.0;     ///< largest |r - r_exact(theta)| / a over the trail's vertices
  double turned = 0.0;    ///< angle the trail sweeps about the star [rad]
  bool broken = false;    ///< a NaN (a break) in the line
  std::size_t lines = 0;  ///< outlines labelled "orbits" with the planet's trail
};

/// Runs kepler with eccentricity e for one period and measures the planet's trail against the ellipse
/// r(theta) = a (1 - e^2) / (1 - e cos theta) of an orbit started at aphelion on +x (the star at 0).
Orbit one_orbit(double e, Snapshot* out = nullptr) {
  RunConfig cfg = RunConfig::from_scene("kepler");
  cfg.set("scene.e", std::to_string(e), "test");
  cfg.set("time.dt", "0", "test");       // the adaptive step that resolves the pericentre (README)
  cfg.set("time.cfl", "0.001", "test");
  World w(cfg);
  TrailLog trails;
  trails.record(w);
  const double r0 = 1.0, a = r0 / (1.0 + e), period = std::sqrt(a * a * a);  // years (G = 4 pi^2)
  while (w.time() < period) {
    w.step(period - w.time());
    trails.record(w);
  }
  Snapshot s = w.report().snapshot();
  trails.decorate(s);
  Orbit o;
  double last = 0.0;
  bool first = true;
  for (const Outline& l : s.outlines) {
    if (l.label != TrailLog::kLabel || std::hypot(l.x.front(), l.y.front()) < 0.5) continue;  // the star's
    ++o.lines;
    for (std::size_t k = 0; k < l.x.size(); ++k) {
      if (!std::isfinite(l.x[k]) || !std::isfinite(l.y[k])) { o.broken = true; continue; }
      const double th = std::atan2(l.y[k], l.x[k]), r = std::hypot(l.x[k], l.y[k]);
      o.worst = std::max(o.worst, std::abs(r - a * (1 - e * e) / (1 - e * std::cos(th))) / a);
      if (!first) {
        double d = th - last;  // unwrapped
        if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
        if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
        o.turned += d;
      }
      last = th;
      first = false;
    }
  }
  if (out) *out = s;
  return o;
}

TEST(TrailLog, KeplerTrailIsOneClosedLineOnTheEllipse) {
  for (double e : {0.0, 0.5}) {
    const Orbit o = one_orbit(e);
    std::printf("kepler e = %.1f: one period, trail within %.2e a of the ellipse, swept %.4f turns\n", e, o.worst,
                o.turned / (2 * std::numbers::pi));
    EXPECT_EQ(o.lines, 1u) << e;
    EXPECT_FALSE(o.broken) << e;
    EXPECT_LT(o.worst, 1e-3) << e;                               // on the exact orbit (float vertices, leapfrog)
    EXPECT_NEAR(o.turned, 2 * std::numbers::pi, 0.02) << e;      // closed: one whole turn
  }
}

TEST(TrailLog, KeplerReferenceDrawsTheExactEllipse) {
  Snapshot s;
  one_orbit(0.5, &s);
  const auto it = std::find_if(s.outlines.begin(), s.outlines.end(), [](const Outline& o) { return o.label == "Kepler orbit"; });
  ASSERT_NE(it, s.outlines.end());
  const double a = 1.0 / 1.5, e = 0.5;
  for (std::size_t k = 0; k < it->x.size(); ++k) {
    const double th = std::atan2(it->y[k], it->x[k]), r = std::hypot(it->x[k], it->y[k]);
    ASSERT_NEAR(r, a * (1 - e * e) / (1 - e * std::cos(th)), 1e-6) << k;
  }
}

TEST(TrailLog, TheGuisStepperPublishesTheTrailOfEveryStep) {
  // the GUI's engine thread runs a year of the Earth's orbit (500 steps) as fast as it can; its frames
  // carry the trail of every step, however few of them a display would draw
  RunConfig cfg = RunConfig::from_scene("kepler");
  cfg.params.time.t_end = 1.0;
  StepperOptions opt;
  opt.start_running = true;
  Stepper s(cfg, opt);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!(s.latest() && s.latest()->at_end) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const StepperFrame* f = s.latest();
  ASSERT_TRUE(f && f->at_end);
  std::size_t planet = 0;
  for (const Outline& o : f->snapshot.outlines) {
    if (o.label != TrailLog::kLabel || std::hypot(o.x.front(), o.y.front()) < 0.5) continue;
    planet = o.x.size();
    for (std::size_t k = 0; k < o.x.size(); ++k) ASSERT_TRUE(std::isfinite(o.x[k]) && std::isfinite(o.y[k])) << k;
  }
  // a step moves the Earth 2 pi 0.002 AU, more than the spacing (2e-3 of the first extent, 1 AU): a vertex
  // per step, the start included
  EXPECT_EQ(planet, static_cast<std::size_t>(f->snapshot.step) + 1);
  EXPECT_EQ(f->snapshot.step, 500);
}

/// Revolutions of a trail about (cx, cy), unwrapped.
double turns_of(const Outline& o, double cx, double cy) {
  double turned = 0.0;
  for (std::size_t k = 1; k < o.x.size(); ++k) {
    double d = std::atan2(o.y[k] - cy, o.x[k] - cx) - std::atan2(o.y[k - 1] - cy, o.x[k - 1] - cx);
    if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
    if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
    turned += d;
  }
  return std::abs(turned) / (2 * std::numbers::pi);
}

TEST(TrailLog, ATrailShowsItsLastRevolutionAndAQuarter) {
  // 20 years of the Solar System: Mercury goes round 83 times (its trail, each turn a little turned, was an
  // annulus), Pluto not once (its whole trail stays)
  RunConfig cfg = RunConfig::from_scene("solar_system");
  World w(cfg);
  TrailLog t;
  t.record(w);
  while (w.time() < 20.0) {
    w.step(20.0 - w.time());
    t.record(w);
  }
  Snapshot s = w.report().snapshot();
  t.decorate(s);
  std::vector<const Outline*> trails;
  for (const Outline& o : s.outlines)
    if (o.label == TrailLog::kLabel) trails.push_back(&o);
  ASSERT_EQ(trails.size(), 10u);  // the Sun and nine bodies, in id order
  const double mercury = turns_of(*trails[1], 0.0, 0.0), pluto = turns_of(*trails[9], 0.0, 0.0);
  std::printf("trail of Mercury: %.3f turns (%zu of %zu vertices), of Pluto: %.3f turns (%zu vertices)\n", mercury,
              trails[1]->x.size(), t.points(1), pluto, trails[9]->x.size());
  EXPECT_GT(mercury, 1.0);
  EXPECT_LE(mercury, TrailLog::kTurns + 0.1);  // the centre of mass is within 0.01 AU of the origin
  EXPECT_LT(trails[1]->x.size(), t.points(1) / 50);
  EXPECT_GE(trails[9]->x.size(), t.points(9));  // every vertex (and the planet now, if it moved since)
  EXPECT_LT(pluto, 0.1);
}

TEST(TrailLog, OnlyFewPointMassesAndRestartsWithTheRun) {
  World gas(RunConfig::from_scene("sod"));
  EXPECT_FALSE(TrailLog::applies(gas));
  RunConfig dust = RunConfig::from_scene("dust_sphere");  // 3D: no trails
  dust.set("scene.n", "50", "test");
  EXPECT_FALSE(TrailLog::applies(World(dust)));
  World k(RunConfig::from_scene("kepler"));
  ASSERT_TRUE(TrailLog::applies(k));
  TrailLog t;
  t.record(k);
  for (int i = 0; i < 50; ++i) {
    k.step(1.0);
    t.record(k);
  }
  const std::size_t grown = t.points(1);
  EXPECT_GT(grown, 10u);
  World again(RunConfig::from_scene("kepler"));  // back at t = 0: a new trail
  t.record(again);
  EXPECT_EQ(t.points(1), 1u);
}

}  // namespace
}  // namespace sph

// A parameter sweep on the threaded stepper (Stepper::set_sweep, stepper/follower_runs.h): every run of the
// sweep is stepped to run A's time, carries its own key=value, and a run given A's own value is A bit for
// bit (the runs are independent Worlds of one configuration); a bad value changes nothing and says why;
// an A/B comparison replaces a sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sph/stepper.h"
#include "stepper_wait.h"

namespace sph {
namespace {

RunConfig small_sod() {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "60", "test");
  cfg.set("kernel.eta", "1.2", "test");
  cfg.params.time.t_end = 0.05;
  return cfg;
}

const SnapshotField& field(const Snapshot& s, const std::string& name) {
  const SnapshotField* f = s.find(name);
  if (f == nullptr) throw std::runtime_error("no field " + name);
  return *f;
}

TEST(FollowerRuns, EverySweepRunReachesAsTimeWithItsOwnValue) {
  StepperOptions opt;
  opt.start_running = false;
  Stepper s(small_sod(), opt);
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.snapshot.count > 0; }));
  s.set_sweep("kernel.eta", {"1.0", "1.2", "1.5"});
  s.resume();
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.at_end && f.sweep.size() == 3; }));
  const StepperFrame& f = *s.latest();
  EXPECT_EQ(f.sweep_key, "kernel.eta");
  EXPECT_FALSE(f.comparing);
  EXPECT_TRUE(f.error.empty()) << f.error;
  const double etas[3] = {1.0, 1.2, 1.5};
  for (int i = 0; i < 3; ++i) {
    const CompareFrame& r = f.sweep[static_cast<std::size_t>(i)];
    EXPECT_EQ(r.snapshot.t, f.snapshot.t) << i;  // stepped to A's time (its last step shortened to land there)
    EXPECT_EQ(r.config.params.kernel.eta, etas[i]) << i;
    ASSERT_EQ(r.overrides.size(), 1u);
  }
  // eta = 1.2 is run A's own value: the same run up to the rounding of its steps, which land on A's times
  // (t_A - t_B, not its own dt), which World::advance_to takes as its dt: bit for bit
  const auto& ra = field(f.snapshot, "rho").values;
  const auto& r12 = field(f.sweep[1].snapshot, "rho").values;
  ASSERT_EQ(ra.size(), r12.size());
  double same = 0.0;
  for (std::size_t i = 0; i < ra.size(); ++i) same = std::max(same, std::abs(double(ra[i]) - r12[i]));
  std::printf("largest |rho_A - rho(eta = 1.2)| = %.3g, |rho_A - rho(eta = 1.0)| = ", same);
  EXPECT_EQ(same, 0.0);
  // other etas are other runs: the densities differ somewhere by more than rounding
  const auto& r10 = field(f.sweep[0].snapshot, "rho").values;
  double most = 0.0;
  for (std::size_t i = 0; i < ra.size(); ++i) most = std::max(most, std::abs(double(ra[i]) - r10[i]));
  std::printf("%.3g\n", most);
  EXPECT_GT(most, 1e-3);
}

TEST(FollowerRuns, ARefusedValueChangesNothingAndNamesIt) {
  StepperOptions opt;
  opt.start_running = false;
  Stepper s(small_sod(), opt);
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.snapshot.count > 0; }));
  s.set_sweep("kernel.eta", {"1.0", "9"});  // outside [0, 4]
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return !f.error.empty(); }));
  const StepperFrame& f = *s.latest();
  EXPECT_TRUE(f.sweep.empty());
  EXPECT_NE(f.error.find("sweep"), std::string::npos) << f.error;
  EXPECT_NE(f.error.find("kernel.eta"), std::string::npos) << f.error;
}

TEST(FollowerRuns, ACompareReplacesASweepAndAnEmptySweepStopsIt) {
  StepperOptions opt;
  opt.start_running = false;
  Stepper s(small_sod(), opt);
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.snapshot.count > 0; }));
  s.set_sweep("kernel.eta", {"1.0", "1.5"});
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.sweep.size() == 2; }));
  s.set_compare({"visc.alpha=0"});
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.comparing && f.sweep.empty(); }));
  s.set_sweep("kernel.eta", {"1.0"});
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return !f.comparing && f.sweep.size() == 1; }));
  s.set_sweep("kernel.eta", {});
  ASSERT_TRUE(test::wait_for(s, [](const StepperFrame& f) { return f.sweep.empty() && f.sweep_key.empty(); }));
}

}  // namespace
}  // namespace sph

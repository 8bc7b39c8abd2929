// The team chooser keeps the faster of one thread and the full team, from timed steps, and measures
// again after a while.
#include "core/team_size.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace sph {
namespace {

/// Runs `steps` steps through the chooser with step times t(team) and returns the teams used.
template <class Time>
std::vector<int> drive(TeamChooser& c, int max_threads, int steps, Time t) {
  std::vector<int> used;
  for (int s = 0; s < steps; ++s) {
    const int team = c.next(max_threads);
    used.push_back(team);
    c.record(t(team));
  }
  return used;
}

TEST(TeamChooser, KeepsTheFullTeamWhenItIsFaster) {
  TeamChooser c;
  const auto used = drive(c, 2, 40, [](int team) { return team == 2 ? 0.6 : 1.0; });
  EXPECT_EQ(c.chosen(), 2);
  EXPECT_EQ(used.back(), 2);
}

TEST(TeamChooser, FallsBackToOneThreadWhenTheTeamIsSlower) {
  // a busy second core: every barrier waits, two threads take 1.5x the time of one
  TeamChooser c;
  const auto used = drive(c, 2, 40, [](int team) { return team == 2 ? 1.5 : 1.0; });
  EXPECT_EQ(c.chosen(), 1);
  EXPECT_EQ(used.back(), 1);
}

TEST(TeamChooser, WithinTheNoiseItKeepsTheTeam) {
  TeamChooser c;
  drive(c, 2, 40, [](int team) { return team == 2 ? 1.0 : 0.97; });
  EXPECT_EQ(c.chosen(), 2);
}

TEST(TeamChooser, MeasuresAgainAndFollowsAChangedMachine) {
  TeamChooser c;
  drive(c, 2, 40, [](int team) { return team == 2 ? 1.5 : 1.0; });
  ASSERT_EQ(c.chosen(), 1);
  // the other core becomes free: after the next measurement the team is used again
  const auto used = drive(c, 2, 600, [](int team) { return team == 2 ? 0.55 : 1.0; });
  EXPECT_EQ(c.chosen(), 2);
  EXPECT_EQ(used.back(), 2);
}

TEST(TeamChooser, AFarSlowerTeamCostsOneStepPerProbe) {
  // spinning threads beside a busy core: a team step 17x slower than one thread's
  TeamChooser c;
  const auto used = drive(c, 2, 2000, [](int team) { return team == 2 ? 17.0 : 1.0; });
  EXPECT_EQ(c.chosen(), 1);
  const auto team_steps = std::count(used.begin(), used.end(), 2);
  // probes at steps 0, 517 and 1546 (each one-thread win doubles the interval): one team step each
  EXPECT_EQ(team_steps, 3);
  // the time lost stays below 10% of a one-thread run
  EXPECT_LT(team_steps * 16.0, 0.1 * 2000);
}

TEST(TeamChooser, SlowerStepsMeasureAgainBeforeTheInterval) {
  TeamChooser c;
  drive(c, 2, 20, [](int team) { return team == 2 ? 0.5 : 1.0; });
  ASSERT_EQ(c.chosen(), 2);
  // the other core gets busy 20 steps in: the team's steps triple; within two watch periods and a
  // probe (well before the 256-step interval) the chooser runs one thread
  const auto used = drive(c, 2, 60, [](int team) { return team == 2 ? 1.5 : 1.0; });
  EXPECT_EQ(c.chosen(), 1);
  EXPECT_EQ(used.back(), 1);
}

TEST(TeamChooser, OneThreadAllowedMeansOneThread) {
  TeamChooser c;
  const auto used = drive(c, 1, 20, [](int) { return 1.0; });
  for (int t : used) EXPECT_EQ(t, 1);
}

}  // namespace
}  // namespace sph

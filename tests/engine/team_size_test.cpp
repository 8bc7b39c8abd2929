// The team chooser keeps the faster of one thread and the full team, from timed steps, and measures
// again after a while.
#include "core/team_size.h"

#include <gtest/gtest.h>

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

TEST(TeamChooser, OneThreadAllowedMeansOneThread) {
  TeamChooser c;
  const auto used = drive(c, 1, 20, [](int) { return 1.0; });
  for (int t : used) EXPECT_EQ(t, 1);
}

}  // namespace
}  // namespace sph

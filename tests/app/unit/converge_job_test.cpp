// The GUI's convergence job: the study runs on its own thread, poll() says when it is over, and the
// result equals the same study run directly; a failing run becomes an error message, not a crash.
#include "converge_job.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace sph::gui {
namespace {

ConvergenceStudy small() {
  ConvergenceStudy s;
  s.key = "scene.n";
  s.values = {60, 120};
  s.t = 0.5;
  s.column = "e_seed";
  return s;
}

void wait(ConvergeJob& job) {
  for (int i = 0; i < 6000 && job.poll(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

TEST(ConvergeJob, RunsTheStudyOnItsThreadAndMatchesADirectRun) {
  const RunConfig base = RunConfig::from_scene("burgers_upwind");
  ConvergeJob job(base, small());
  wait(job);
  ASSERT_FALSE(job.poll());
  ASSERT_TRUE(job.result().has_value()) << job.error();
  EXPECT_EQ(job.finished(), 2);
  const ConvergenceResult direct = run_convergence(base, small());
  ASSERT_EQ(job.result()->runs.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(job.result()->runs[k].error, direct.runs[k].error);
}

TEST(ConvergeJob, AFailingRunBecomesAnErrorMessage) {
  ConvergenceStudy s = small();
  s.values = {60, 3};  // scene.n = 3 is below the scene's minimum (8)
  ConvergeJob job(RunConfig::from_scene("burgers_upwind"), s);
  wait(job);
  EXPECT_FALSE(job.result().has_value());
  EXPECT_NE(job.error().find("scene.n"), std::string::npos) << job.error();
}

}  // namespace
}  // namespace sph::gui

// The lesson panel's check runs on its own thread and gives the result evaluate_check gives directly.
#include "lesson_job.h"

#include <gtest/gtest.h>

namespace sph::gui {
namespace {

TEST(LessonJob, MatchesADirectCheck) {
  LessonStep st;
  st.scene = "sod";
  st.sets = {{"scene.n_left", "60"}};
  st.check.type = LessonCheck::Type::Below;
  st.check.metric = "L1_rho";
  st.check.until = 0.05;
  st.check.limit = 1.0;
  LessonJob job(st);
  job.wait();
  EXPECT_FALSE(job.poll());
  ASSERT_TRUE(job.result().has_value()) << job.error();
  const CheckResult direct = evaluate_check(st);
  EXPECT_EQ(job.result()->measured, direct.measured);
  EXPECT_EQ(job.result()->text, direct.text);
  EXPECT_TRUE(job.result()->pass);
}

}  // namespace
}  // namespace sph::gui

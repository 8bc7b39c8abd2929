// Projector mode's scale steps: Ctrl+= / Ctrl+- move by 0.25 on a grid, clamped to 1..3.
#include <gtest/gtest.h>

#include "ui_look.h"

namespace sph::gui {
namespace {

TEST(UiScale, StepsOnTheGridAndClamps) {
  EXPECT_FLOAT_EQ(step_ui_scale(1.f, 1), 1.25f);
  EXPECT_FLOAT_EQ(step_ui_scale(1.f, 4), 2.f);
  EXPECT_FLOAT_EQ(step_ui_scale(2.f, -1), 1.75f);
  EXPECT_FLOAT_EQ(step_ui_scale(1.f, -1), 1.f);
  EXPECT_FLOAT_EQ(step_ui_scale(3.f, 1), 3.f);
  EXPECT_FLOAT_EQ(step_ui_scale(1.37f, 0), 1.25f);  // a slider's value put on the grid
  EXPECT_FLOAT_EQ(step_ui_scale(1.4f, 0), 1.5f);
}

}  // namespace
}  // namespace sph::gui

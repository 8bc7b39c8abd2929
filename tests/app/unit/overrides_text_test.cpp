// The compare panel's field: run B's overrides typed with commas, semicolons or newlines and spaces.
#include <gtest/gtest.h>

#include "overrides_text.h"

namespace sph::gui {
namespace {

TEST(OverridesText, SplitsAndTrims) {
  EXPECT_EQ(split_overrides("kernel.type=M6"), (std::vector<std::string>{"kernel.type=M6"}));
  EXPECT_EQ(split_overrides(" visc.alpha=0 ,visc.beta=0;\n time.integrator=rk4 ,, "),
            (std::vector<std::string>{"visc.alpha=0", "visc.beta=0", "time.integrator=rk4"}));
  EXPECT_TRUE(split_overrides("  , ").empty());
}

}  // namespace
}  // namespace sph::gui

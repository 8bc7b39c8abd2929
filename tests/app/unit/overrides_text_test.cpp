// The compare panel's field: run B's overrides typed with commas, semicolons or newlines and spaces; a
// sweep as KEY=V1,V2 (--sweep) and its values as the sweep panel takes them.
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

TEST(OverridesText, ASweepIsAKeyAndItsValues) {
  std::string key, err;
  std::vector<std::string> values;
  ASSERT_TRUE(split_sweep("kernel.eta=1.0, 1.5;2", &key, &values, &err));
  EXPECT_EQ(key, "kernel.eta");
  EXPECT_EQ(values, (std::vector<std::string>{"1.0", "1.5", "2"}));
  EXPECT_EQ(split_values(" 1.0 1.5,\n2 "), (std::vector<std::string>{"1.0", "1.5", "2"}));
  for (const char* bad : {"kernel.eta", "kernel.eta=", "=1,2", "kernel.eta= , "}) {
    EXPECT_FALSE(split_sweep(bad, &key, &values, &err)) << bad;
    EXPECT_NE(err.find("is not KEY=V1,V2"), std::string::npos) << err;
  }
}

}  // namespace
}  // namespace sph::gui

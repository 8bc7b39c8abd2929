// Progress bar text and its silence when stderr is not a terminal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "progress.h"

namespace sph::cli {
namespace {

TEST(Progress, DurationFormat) {
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(65.2), "1:05");
  EXPECT_EQ(format_duration(3665.0), "1:01:05");
  EXPECT_EQ(format_duration(-1.0), "--:--");
  EXPECT_EQ(format_duration(NAN), "--:--");
}

TEST(Progress, BarText) {
  EXPECT_EQ(Progress::format(0.5, 0.1, 120, 3.0, 3.0, 10),
            "[#####-----]  50.0%  t = 0.1000  step 120  elapsed 0:03  ETA 0:03");
  EXPECT_EQ(Progress::format(2.0, 1.0, 7, 1.0, -1.0, 4), "[####] 100.0%  t = 1.0000  step 7  elapsed 0:01  ETA --:--");
  EXPECT_EQ(Progress::format(0.25, 0.05, -1, 1.0, 3.0, 4), "[#---]  25.0%  t = 0.0500  elapsed 0:01  ETA 0:03");
}

TEST(Progress, SilentWhenNotATerminal) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress bar(1.0, 0.0, f);
    EXPECT_FALSE(bar.enabled());
    bar.update(0.5, 10, true);
    bar.update(1.0);
    bar.finish();
  }
  EXPECT_EQ(std::ftell(f), 0L);
  std::fclose(f);
}

}  // namespace
}  // namespace sph::cli

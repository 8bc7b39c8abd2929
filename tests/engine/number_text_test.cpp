// Doubles as text (text/number_text.h): exact_text reads back to the same double with the fewest digits,
// without an exponent where plain digits do (messages show "[4, 1000000]", not "[4.000000, 1000000.000000]").
#include "text/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

namespace sph {
namespace {

TEST(NumberText, ExactTextIsShortWhereThatIsExact) {
  EXPECT_EQ(exact_text(0.1), "0.1");
  EXPECT_EQ(exact_text(0.2), "0.2");
  EXPECT_EQ(exact_text(100.0), "100");
  EXPECT_EQ(exact_text(1e6), "1000000");
  EXPECT_EQ(exact_text(-2.5), "-2.5");
  EXPECT_EQ(exact_text(1e-4), "0.0001");
  EXPECT_EQ(exact_text(1e20), "1e+20");
  EXPECT_EQ(exact_text(1e-7), "1e-07");
  EXPECT_EQ(exact_text(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(exact_text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(exact_text(std::nan("")), "nan");
}

TEST(NumberText, ExactTextReadsBackToTheSameDouble) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 20000; ++k) {
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    ASSERT_EQ(std::strtod(exact_text(v).c_str(), nullptr), v) << exact_text(v);
  }
  for (double v : {5e-324, 1.7976931348623157e308, 0.0, -0.0, 123456789012345.6})
    EXPECT_EQ(std::strtod(exact_text(v).c_str(), nullptr), v) << exact_text(v);
}

}  // namespace
}  // namespace sph

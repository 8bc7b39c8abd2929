// The automatic colour range (app/render/field_range.h): between percentiles, so that one outlier does
// not squeeze every other particle into the bottom colour; walls and non-finite values left out.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "field_range.h"
#include "sph/snapshot.h"

namespace sph::render {
namespace {

SnapshotField field_with_outlier() {
  SnapshotField f{"rho", "density rho", {}, 0, 0};
  for (int i = 0; i < 1000; ++i) f.values.push_back(1.f + static_cast<float>(i) / 999.f);  // 1 .. 2
  f.values[500] = 1e6f;                                                                    // one outlier
  f.min = 1.f;
  f.max = 1e6f;
  return f;
}

TEST(FieldRange, PercentilesIgnoreOneOutlier) {
  const SnapshotField f = field_with_outlier();
  ViewSettings v;
  v.percentile_lo = 1.f;
  v.percentile_hi = 99.f;
  const ValueRange r = resolve_range(f, v);
  EXPECT_NEAR(r.min, 1.01f, 0.002f);
  EXPECT_NEAR(r.max, 1.99f, 0.002f);
  // min/max (0, 100; the headless default) is what it was: the outlier sets the top
  v.percentile_lo = 0.f;
  v.percentile_hi = 100.f;
  EXPECT_EQ(resolve_range(f, v).max, 1e6f);
  EXPECT_EQ(resolve_range(f, v).min, 1.f);
}

TEST(FieldRange, PercentilesLeaveOutWallsAndNonFiniteValues) {
  const std::vector<float> values = {5.f, NAN, 1.f, INFINITY, 3.f, 100.f, 2.f, 4.f};
  const std::vector<std::uint8_t> kind = {0, 0, 0, 0, 0, 1, 0, 0};  // 100 is a wall
  const ValueRange all = percentile_range(values, 0.f, 100.f, kind);
  EXPECT_EQ(all.min, 1.f);
  EXPECT_EQ(all.max, 5.f);
  const ValueRange mid = percentile_range(values, 25.f, 75.f, kind);  // ranks 1 and 3 of 1..5
  EXPECT_EQ(mid.min, 2.f);
  EXPECT_EQ(mid.max, 4.f);
  const std::vector<float> none = {NAN, NAN};
  EXPECT_EQ(percentile_range(none, 1.f, 99.f).max, 0.f);
}

TEST(FieldRange, ConstantFieldIsWidenedUnderPercentilesToo) {
  SnapshotField f{"u", "u", std::vector<float>(50, 0.7f), 0.7f, 0.7f};
  ViewSettings v;
  v.percentile_lo = 1.f;
  v.percentile_hi = 99.f;
  const ValueRange r = resolve_range(f, v);
  EXPECT_LT(r.min, 0.7f);
  EXPECT_GT(r.max, 0.7f);
}

TEST(FieldRange, SpansDecadesBetweenItsPercentiles) {
  std::vector<float> v;
  for (int i = 0; i < 1000; ++i) v.push_back(std::pow(10.f, 3.f * static_cast<float>(i) / 999.f));  // 1 .. 1000
  EXPECT_TRUE(spans_decades(v));
  for (float& x : v) x = 1.f + x / 1000.f;  // 1 .. 2
  EXPECT_FALSE(spans_decades(v));
  v[0] = 1e-6f;  // one outlier below the 1st percentile does not make it span decades
  EXPECT_FALSE(spans_decades(v));
  std::vector<float> signed_values(v.size(), 1.f);
  for (std::size_t i = 0; i < 50; ++i) signed_values[i] = -5.f;  // 5% non-positive: no log10
  signed_values.back() = 1e6f;
  EXPECT_FALSE(spans_decades(signed_values));
}

}  // namespace
}  // namespace sph::render

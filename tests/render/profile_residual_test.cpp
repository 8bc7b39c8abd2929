// The residual strip of profiles (app/render/profile_residual.h): B - A at A's particles for two 1D runs
// (an M4-against-M6 comparison drew B's dots on A's and looked like one run), each run minus the exact
// curve otherwise, and the strip drawn under the panel in B's colour.
#include <gtest/gtest.h>

#include <cmath>

#include "frame_scene.h"
#include "profile_residual.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

/// The panel a comparison draws of field 0: run A and B's values and the exact curve of `s`.
ProfilePanel panel_of(const Snapshot& a, const Snapshot* b) {
  ProfilePanel p;
  for (const Snapshot* s : {&a, b}) {
    if (s == nullptr) continue;
    ProfileRun r;
    r.snap = s;
    r.run = s == &a ? 0 : 1;
    r.solid = kRunColors[r.run];
    r.y.assign(s->fields.front().values.begin(), s->fields.front().values.end());
    p.runs.push_back(r);
  }
  p.curve = curve_of(a, a.fields.front().name, 0, false);
  if (b) p.versus_first = "B - A";
  return p;
}

TEST(ProfileResidual, ExactAtInterpolatesLinearlyAndIsNaNOutsideTheCurve) {
  sph::ExactCurve c;
  c.x = {0.f, 1.f, 1.f, 3.f};  // a jump at x = 1 (two samples there, as the engine's curves have)
  c.value = {0.f, 2.f, 5.f, 9.f};
  EXPECT_FLOAT_EQ(exact_at(c, 0.25f), 0.5f);
  EXPECT_FLOAT_EQ(exact_at(c, 2.f), 7.f);
  EXPECT_FLOAT_EQ(exact_at(c, 3.f), 9.f);
  EXPECT_TRUE(std::isnan(exact_at(c, -0.1f)));
  EXPECT_TRUE(std::isnan(exact_at(c, 3.1f)));
}

TEST(ProfileResidual, TwoOneDRunsGiveBMinusAAtAsParticles) {
  const Snapshot a = sod_profile_1d(400), b = sod_profile_1d_run_b(400);
  const ProfilePanel p = panel_of(a, &b);
  ASSERT_TRUE(has_residuals(p));
  const ProfilePanel r = residual_panel(p, 0);
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.y_title.rfind("B - A", 0), 0u);
  const std::vector<float>& d = r.runs[0].y;
  float largest = 0.f;
  for (std::size_t i = 0; i < a.count; ++i) {
    const float expect = a.x[i] > 0.f && a.x[i] < 0.15f ? -0.2f * a.fields[0].values[i] : 0.f;
    if (a.x[i] > 0.005f && a.x[i] < 0.145f) {
      EXPECT_NEAR(d[i], expect, 1e-6f) << i;  // B at A's x: the same x
    }
    if (a.x[i] < -0.01f || a.x[i] > 0.16f) {
      EXPECT_NEAR(d[i], 0.f, 1e-6f) << i;
    }
    largest = std::max(largest, std::abs(d[i]));
  }
  EXPECT_GT(largest, 0.05f);
  EXPECT_NEAR(r.y1, 1.1 * largest, 1e-6);  // symmetric about the zero line
  EXPECT_EQ(r.y0, -r.y1);
  EXPECT_EQ(r.runs[0].solid.b, kRunColors[1].b);  // in B's colour
}

TEST(ProfileResidual, OneRunGivesItsValuesMinusTheExactCurve) {
  const Snapshot a = sod_profile_1d(400);
  const ProfilePanel p = panel_of(a, nullptr);
  const ProfilePanel r = residual_panel(p, 0);
  ASSERT_EQ(r.runs.size(), 1u);
  for (std::size_t i = 0; i < a.count; i += 7)
    EXPECT_NEAR(r.runs[0].y[i], a.fields[0].values[i] - exact_at(p.curve, a.x[i]), 1e-6f);
  ProfilePanel bare = p;
  bare.curve = {};
  EXPECT_FALSE(has_residuals(bare));  // nothing to subtract
}

class RenderResidual : public OffscreenTest {};

TEST_F(RenderResidual, AComparisonDrawsItsStripUnderTheProfileInBsColour) {
  const Snapshot a = sod_profile_1d(400), b = sod_profile_1d_run_b(400);
  const auto rgba = render(m4_against_m6(a, b), ViewSettings{});
  const PixelRect plot = layout().plot;
  EXPECT_LT(plot.bottom(), 0.75f * kHeight);  // the profile leaves the strip its room
  // B - A = -0.2 rho on (0, 0.15), 0 on the left: B's dots under the profile's box, lower on that interval
  const Pixel cb = to_pixel8(kRunColors[1]);
  const auto first_b_below = [&](float x) {
    float px, py;
    EXPECT_TRUE(layout().to_pixel(x, 0.5f, 0.f, &px, &py));
    for (float y = plot.bottom() + 4.f; y < kHeight - 1.f; y += 1.f)
      if (colour_near(rgba, kWidth, kHeight, px, y, cb, 0, 20)) return y;
    return -1.f;
  };
  for (float x : {-0.44f, -0.4f, -0.36f}) {
    const float zero = first_b_below(x), low = first_b_below(x + 0.5f);  // x + 0.5 in (0.06, 0.14)
    EXPECT_GT(zero, 0.f) << x;
    EXPECT_GT(low, zero + 15.f) << x;
  }
}

}  // namespace
}  // namespace sph::render::test

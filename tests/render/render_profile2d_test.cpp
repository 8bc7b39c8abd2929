// The 2D profile view (ViewSettings::profile_axis): the field against x or y of a 2D snapshot, one
// dot per fluid particle at (coordinate, value), walls left out, and the reference curve of that field
// along that axis drawn over them; ignored by 1D and 3D snapshots.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

constexpr int kNx = 20, kNy = 10;

class RenderProfile2D : public OffscreenTest {
 protected:
  bool near(const std::vector<std::uint8_t>& rgba, float coord, float value, Pixel c, int radius, int tol) const {
    float px = 0, py = 0;
    EXPECT_TRUE(layout().to_pixel(coord, value, 0.f, &px, &py));
    EXPECT_TRUE(layout().plot.contains(px, py)) << coord << ", " << value;
    return colour_near(rgba, kWidth, kHeight, px, py, c, radius, tol);
  }
};

TEST_F(RenderProfile2D, ParticlesSitAtTheirCoordinateAndValue) {
  const Snapshot s = lattice_2d(kNx, kNy);  // rho = 1 + x, p = y
  for (int axis : {0, 1}) {
    ViewSettings v;
    v.profile_axis = axis;
    v.color_by = "rho";
    const auto rgba = render(s, v);
    const SnapshotField& rho = *s.find("rho");
    for (auto [i, j] : {std::pair{0, 0}, {4, 7}, {13, 2}, {19, 9}}) {
      const std::size_t k = lattice_index(kNx, i, j);
      const float coord = axis == 0 ? s.x[k] : s.y[k];
      const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, (rho.values[k] - rho.min) / (rho.max - rho.min)));
      EXPECT_TRUE(near(rgba, coord, rho.values[k], want, 1, 6)) << "axis " << axis << " particle " << i << "," << j;
    }
    // The horizontal axis spans that coordinate's extent: [0, 2] for x, [0, 1] for y.
    float x0, x1, py;
    ASSERT_TRUE(layout().to_pixel(0.f, 2.f, 0.f, &x0, &py));
    ASSERT_TRUE(layout().to_pixel(axis == 0 ? 2.f : 1.f, 2.f, 0.f, &x1, &py));
    EXPECT_GT(x1 - x0, 0.9f * layout().plot.w) << "axis " << axis;
    EXPECT_LT(x1 - x0, layout().plot.w) << "axis " << axis;
  }
}

TEST_F(RenderProfile2D, NothingWhereNoParticleIs) {
  const Snapshot s = lattice_2d(kNx, kNy);
  ViewSettings v;
  v.profile_axis = 0;
  v.color_by = "rho";  // against x: a thin diagonal rho = 1 + x
  const auto rgba = render(s, v);
  float px, py;
  ASSERT_TRUE(layout().to_pixel(0.65f, 2.65f, 0.f, &px, &py));  // far above the diagonal, between grid lines
  EXPECT_EQ(count_drawn(rgba, kWidth, {px - 3, py - 3, 6, 6}), 0);
}

TEST_F(RenderProfile2D, WallsAreLeftOut) {
  const Snapshot s = tank_2d(kNx, kNy);  // walls at 1000, far above the fluid's range
  ViewSettings v;
  v.profile_axis = 1;
  v.color_by = "p";
  const auto rgba = render(s, v);
  float px, py;
  ASSERT_TRUE(layout().to_pixel(0.5f, kWallValue, 0.f, &px, &py));
  EXPECT_FALSE(layout().plot.contains(px, py));  // the vertical range is the fluid's
  EXPECT_EQ(count_colour(rgba, kWidth, layout().plot, to_pixel8(palette::kWall), 2), 0);
  const SnapshotField& p = *s.find("p");
  const std::size_t k = lattice_index(kNx, 5, 5);
  const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, (p.values[k] - p.min) / (p.max - p.min)));
  EXPECT_TRUE(near(rgba, s.y[k], p.values[k], want, 1, 6));
}

TEST_F(RenderProfile2D, ReferenceCurveOfThatAxisIsDrawn) {
  Snapshot s = lattice_2d(kNx, kNy);
  // "p" = y exactly: along y the curve is the diagonal; the one along x (0.25) must not appear.
  ExactCurve along_y{"p", {0.f, 1.f}, {0.f, 1.f}, 1};
  ExactCurve along_x{"p", {0.f, 2.f}, {0.25f, 0.25f}, 0};
  s.exact = {along_x, along_y};
  ViewSettings v;
  v.profile_axis = 1;
  v.color_by = "p";
  v.cmap = "magma";
  const auto rgba = render(s, v);
  const Pixel curve = to_pixel8(colormap_contrast(Colormap::Magma));
  for (float y : {0.07f, 0.33f, 0.52f, 0.71f})  // (the legend covers the top right)
    EXPECT_TRUE(near(rgba, y, y, curve, 1, 12)) << "y = " << y;
  EXPECT_FALSE(near(rgba, 0.8f, 0.25f, curve, 2, 40));

  v.profile_axis = 0;  // against x: the x curve, at 0.25
  const auto by_x = render(s, v);
  EXPECT_TRUE(near(by_x, 1.5f, 0.25f, curve, 1, 12));
  v.show_exact = false;
  const auto without = render(s, v);
  EXPECT_FALSE(near(without, 1.5f, 0.25f, curve, 2, 40));
}

TEST_F(RenderProfile2D, OneAndThreeDimensionalSnapshotsIgnoreIt) {
  for (const Snapshot& s : {sod_profile_1d(200), ball_3d(500)}) {
    const auto plain = render(s, ViewSettings{});
    ViewSettings v;
    v.profile_axis = 1;
    EXPECT_TRUE(render(s, v) == plain) << s.dim << "D";
  }
}

}  // namespace
}  // namespace sph::render::test

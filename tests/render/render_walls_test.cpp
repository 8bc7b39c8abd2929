// Wall particles (Snapshot::kind): grey in 2D and 3D whatever the colour map and field, on both
// particle paths; hidden on request; left out of profiles; and the colour range stays the fluid's.
#include <gtest/gtest.h>

#include <cmath>

#include "particle_instances.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

constexpr int kNx = 20, kNy = 10;  // discs ~45 px across at 1280x720

class RenderWalls : public OffscreenTest {
 protected:
  void TearDown() override { renderer_->renderer().set_particle_path(ParticlePath::Auto); }

  Pixel centre_of(const std::vector<std::uint8_t>& rgba, const Snapshot& s, std::size_t k) const {
    float px = 0, py = 0;
    EXPECT_TRUE(layout().to_pixel(s.x[k], s.y[k], s.z[k], &px, &py));
    return pixel_at(rgba, kWidth, static_cast<int>(px), static_cast<int>(py));
  }
};

TEST_F(RenderWalls, WallsAreGreyWhateverTheMapFieldAndPath) {
  const Snapshot s = tank_2d(kNx, kNy);
  const Pixel grey = to_pixel8(palette::kWall);
  for (ParticlePath path : {ParticlePath::Gpu, ParticlePath::Cpu}) {
    renderer_->renderer().set_particle_path(path);
    for (auto name : colormap_names())
      for (const char* field : {"rho", "p"}) {
        ViewSettings v;
        v.cmap = std::string(name);
        v.color_by = field;
        const auto rgba = render(s, v);
        const SnapshotField& f = *s.find(field);
        const std::string what = std::string(name) + " " + field + (path == ParticlePath::Cpu ? " cpu" : " gpu");
        // Walls: the bottom row and both side columns.
        for (auto [i, j] : {std::pair{0, 0}, {0, 5}, {0, 9}, {7, 0}, {19, 0}, {19, 6}}) {
          const Pixel got = centre_of(rgba, s, lattice_index(kNx, i, j));
          EXPECT_LE(channel_distance(got, grey), 2) << what << " wall " << i << "," << j << ": " << describe(got);
        }
        // Fluid: the map over the fluid's range (the walls' 1000 would squash it to one end otherwise).
        for (auto [i, j] : {std::pair{1, 1}, {5, 4}, {10, 9}, {18, 3}}) {
          const std::size_t k = lattice_index(kNx, i, j);
          const Pixel want = to_pixel8(colormap_rgb(*parse_colormap(name), (f.values[k] - f.min) / (f.max - f.min)));
          const Pixel got = centre_of(rgba, s, k);
          EXPECT_LE(channel_distance(got, want), 3) << what << " fluid " << i << "," << j << ": got " << describe(got)
                                                    << " want " << describe(want);
        }
      }
  }
}

TEST_F(RenderWalls, HiddenWallsLeaveThePlotFillAndTheFluidUnchanged) {
  const Snapshot s = tank_2d(kNx, kNy);
  ViewSettings v;
  const auto shown = render(s, v);
  v.show_walls = false;
  const auto hidden = render(s, v);
  const Pixel fill = to_pixel8(palette::kPlotFill);
  for (auto [i, j] : {std::pair{0, 5}, {10, 0}, {19, 9}}) {
    const Pixel got = centre_of(hidden, s, lattice_index(kNx, i, j));
    EXPECT_LE(channel_distance(got, fill), 2) << i << "," << j << ": " << describe(got);
  }
  const std::size_t k = lattice_index(kNx, 10, 5);
  EXPECT_EQ(channel_distance(centre_of(hidden, s, k), centre_of(shown, s, k)), 0);
}

TEST_F(RenderWalls, ColourRangeIsTheFluidsEvenWhenRecomputed) {
  Snapshot s = tank_2d(kNx, kNy);
  SnapshotField& rho = s.fields[0];
  const float lo = rho.min, hi = rho.max;
  rho.min = rho.max = NAN;  // stale: the renderer recomputes it, and must leave the walls out
  const ValueRange r = resolve_range(rho, ViewSettings{}, s.kind);
  EXPECT_FLOAT_EQ(r.min, lo);
  EXPECT_FLOAT_EQ(r.max, hi);
  render(s, ViewSettings{});
  EXPECT_GT(layout().colorbar.h, 0.f);
  const ValueRange all = resolve_range(rho, ViewSettings{});  // no kinds: every particle counts
  EXPECT_FLOAT_EQ(all.max, kWallValue);
}

TEST_F(RenderWalls, InstancesFlagWallsAndProfilesLeaveThemOut) {
  const Snapshot s = tank_2d(4, 3);  // 12 particles; walls: the bottom row (4) and both sides above it (4)
  ShownField shown;
  shown.field = s.find("rho");
  std::vector<float> all, fluid, profile;
  build_instances(s, shown, {Placement::Positions, 0, 0.5f, true}, &all);
  build_instances(s, shown, {Placement::Positions, 0, 0.5f, false}, &fluid);
  build_instances(s, shown, {Placement::Profile, 1, 0.f, true}, &profile);
  std::size_t walls = 0;
  for (std::size_t k = 0; k < s.count; ++k) walls += s.is_wall(k);
  ASSERT_EQ(walls, 8u);
  ASSERT_EQ(all.size(), s.count * kInstanceFloats);
  ASSERT_EQ(fluid.size(), (s.count - walls) * kInstanceFloats);
  ASSERT_EQ(profile.size(), fluid.size());
  for (std::size_t k = 0; k < s.count; ++k) EXPECT_EQ(all[k * kInstanceFloats + 5], s.is_wall(k) ? 1.f : 0.f);
  for (std::size_t n = 0; n < fluid.size(); n += kInstanceFloats) {
    EXPECT_EQ(fluid[n + 5], 0.f);
    EXPECT_EQ(profile[n + 0], fluid[n + 1]);  // profile against y: the coordinate is the particle's y
    EXPECT_EQ(profile[n + 1], fluid[n + 4]);  // and the height its value
  }
}

TEST_F(RenderWalls, OneDimensionalProfilesSkipWalls) {
  Snapshot s = sod_profile_1d(200);
  s.kind.assign(s.count, 0);
  for (std::size_t k = 0; k < 10; ++k) {  // the first ten: walls with a value inside the plot
    s.kind[k] = 1;
    s.fields[0].values[k] = 0.55f;
  }
  ViewSettings v;
  v.show_exact = false;
  const auto rgba = render(s, v);
  for (std::size_t k = 0; k < 10; k += 3) {
    float px, py;
    ASSERT_TRUE(layout().to_pixel(s.x[k], 0.55f, 0.f, &px, &py));
    EXPECT_EQ(count_drawn(rgba, kWidth, {px - 3, py - 3, 6, 6}), 0) << "wall " << k << " drawn at its value";
  }
  // The fluid beside them is there (rho ~ 1).
  float px, py;
  ASSERT_TRUE(layout().to_pixel(s.x[12], s.fields[0].values[12], 0.f, &px, &py));
  EXPECT_GT(count_drawn(rgba, kWidth, {px - 3, py - 3, 6, 6}), 10);
}

TEST_F(RenderWalls, ThreeDWallSpheresAreNeutralGreyOnBothPaths) {
  Snapshot s;
  s.scene = "wall3d";
  s.dim = 3;
  s.count = 1;
  s.bounds = {-1, 1, -1, 1, -1, 1};
  s.x = {0.f}, s.y = {0.f}, s.z = {0.f}, s.h = {0.5f};
  s.kind = {1};
  s.fields = {{"rho", "density", {2.f}, 1.f, 3.f}};  // would be green-blue in viridis
  for (ParticlePath path : {ParticlePath::Gpu, ParticlePath::Cpu}) {
    renderer_->renderer().set_particle_path(path);
    ViewSettings v;
    const auto rgba = render(s, v);
    const Pixel p = centre_of(rgba, s, 0);
    EXPECT_LE(std::max(std::abs(p.r - p.g), std::abs(p.g - p.b)), 2) << describe(p);  // lit grey stays grey
    EXPECT_GT(p.r, 80) << describe(p);
    v.show_walls = false;
    const Pixel gone = centre_of(render(s, v), s, 0);
    EXPECT_LE(channel_distance(gone, to_pixel8(palette::kBackground)), 2) << describe(gone);
  }
}

}  // namespace
}  // namespace sph::render::test

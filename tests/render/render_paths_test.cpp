// The two particle paths (GPU quads, CPU splat) draw the same picture: software GL uses the CPU
// splat, a GPU the quads, and a lecture must not look different on either.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class ParticlePaths : public OffscreenTest {
 protected:
  void TearDown() override { renderer_->renderer().set_particle_path(ParticlePath::Auto); }

  // Fraction of pixels whose channels differ by more than `tol`, and the largest difference.
  void compare(const Snapshot& s, const ViewSettings& v, double max_fraction, int tol) {
    renderer_->renderer().set_particle_path(ParticlePath::Gpu);
    ASSERT_FALSE(renderer_->renderer().particles_on_cpu());
    const auto gpu = render(s, v);
    renderer_->renderer().set_particle_path(ParticlePath::Cpu);
    ASSERT_TRUE(renderer_->renderer().particles_on_cpu());
    const auto cpu = render(s, v);
    int off = 0, worst = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const int d = channel_distance(pixel_at(gpu, kWidth, x, y), pixel_at(cpu, kWidth, x, y));
        off += d > tol;
        worst = std::max(worst, d);
      }
    const double fraction = static_cast<double>(off) / (kWidth * kHeight);
    EXPECT_LE(fraction, max_fraction) << "worst channel difference " << worst;
  }
};

TEST_F(ParticlePaths, SoftwareGlChoosesTheCpuSplat) {
  renderer_->renderer().set_particle_path(ParticlePath::Auto);
  EXPECT_TRUE(renderer_->renderer().particles_on_cpu());  // OSMesa runs llvmpipe
}

TEST_F(ParticlePaths, Discs2DAgree) { compare(lattice_2d(20, 10), ViewSettings{}, 1e-4, 3); }

TEST_F(ParticlePaths, ManySmallOverlappingDiscsAgree) { compare(random_cloud(2, 20000), ViewSettings{}, 1e-4, 3); }

TEST_F(ParticlePaths, GreyWallsAgree) {
  ViewSettings v;
  v.cmap = "cividis";  // the map with a grey middle
  compare(tank_2d(20, 10), v, 1e-4, 3);
  Snapshot ball = ball_3d(3000);
  ball.kind.assign(ball.count, 0);
  for (std::size_t k = 0; k < ball.count; k += 3) ball.kind[k] = 1;
  compare(ball, v, 1e-4, 3);
}

TEST_F(ParticlePaths, ProfileDotsAgree) { compare(sod_profile_1d(400), ViewSettings{}, 1e-4, 3); }

TEST_F(ParticlePaths, ShadedSpheresAgree) {
  ViewSettings v;
  v.cmap = "magma";
  compare(ball_3d(3000), v, 1e-4, 3);
}

}  // namespace
}  // namespace sph::render::test

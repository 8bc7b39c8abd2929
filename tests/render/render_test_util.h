// Helpers shared by the off-screen rendering tests: one OSMesa renderer per test suite, pixel access
// and colour comparisons.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "colormap.h"
#include "frame_scene.h"
#include "frame_recorder.h"
#include "palette.h"

namespace sph::render::test {

struct Pixel {
  int r = 0, g = 0, b = 0;
};

inline Pixel pixel_at(const std::vector<std::uint8_t>& rgba, int width, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

inline Pixel to_pixel8(Rgb c) {
  return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255))};
}
inline Pixel to_pixel8(Rgba c) { return to_pixel8(Rgb{c.r, c.g, c.b}); }

/// Largest per-channel difference [0..255].
inline int channel_distance(Pixel a, Pixel b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

inline std::string describe(Pixel p) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "(%d,%d,%d)", p.r, p.g, p.b);
  return buf;
}

/// Pixels inside r whose colour is neither the frame background nor the plot fill.
inline int count_drawn(const std::vector<std::uint8_t>& rgba, int width, const PixelRect& r) {
  const Pixel bg = to_pixel8(palette::kBackground), fill = to_pixel8(palette::kPlotFill);
  int n = 0;
  for (int y = static_cast<int>(r.y); y < static_cast<int>(r.bottom()); ++y)
    for (int x = static_cast<int>(r.x); x < static_cast<int>(r.right()); ++x) {
      const Pixel p = pixel_at(rgba, width, x, y);
      if (channel_distance(p, bg) > 2 && channel_distance(p, fill) > 2) ++n;
    }
  return n;
}

/// Is there a pixel within +-radius of (px, py) whose colour is within tol of c?
inline bool colour_near(const std::vector<std::uint8_t>& rgba, int width, int height, float px, float py, Pixel c,
                        int radius, int tol) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = static_cast<int>(px) + dx, y = static_cast<int>(py) + dy;
      if (x >= 0 && y >= 0 && x < width && y < height && channel_distance(pixel_at(rgba, width, x, y), c) <= tol)
        return true;
    }
  return false;
}

/// Pixels inside r within tol of colour c.
inline int count_colour(const std::vector<std::uint8_t>& rgba, int width, const PixelRect& r, Pixel c, int tol) {
  int n = 0;
  for (int y = static_cast<int>(r.y); y < static_cast<int>(r.bottom()); ++y)
    for (int x = static_cast<int>(r.x); x < static_cast<int>(r.right()); ++x)
      n += channel_distance(pixel_at(rgba, width, x, y), c) <= tol;
  return n;
}

/// One off-screen renderer shared by all tests of a suite (context creation is the slow part).
/// The A/B scene of two snapshots, labelled as an M4-against-M6 comparison.
inline FrameScene m4_against_m6(const Snapshot& a, const Snapshot& b) {
  FrameScene scene;
  scene.a = &a;
  scene.b = &b;
  scene.label_a = "A: kernel.type=M4";
  scene.label_b = "B: kernel.type=M6";
  return scene;
}

class OffscreenTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string err;
    renderer_ = cli::OffscreenRenderer::create(&err).release();
    ASSERT_NE(renderer_, nullptr) << err;
  }
  static void TearDownTestSuite() {
    delete renderer_;
    renderer_ = nullptr;
  }
  void SetUp() override { ASSERT_NE(renderer_, nullptr); }

  /// Renders and checks that GL reported no error.
  std::vector<std::uint8_t> render(const Snapshot& snap, const ViewSettings& view, int w = kWidth, int h = kHeight) {
    std::vector<std::uint8_t> rgba;
    std::string err;
    EXPECT_TRUE(renderer_->render(snap, view, w, h, &rgba, &err)) << err;
    EXPECT_EQ(renderer_->gl_error(), 0u) << "glGetError after rendering";
    EXPECT_EQ(rgba.size(), static_cast<std::size_t>(w) * h * 4);
    return rgba;
  }
  /// A comparison's frame (scene.b set), with the same checks.
  std::vector<std::uint8_t> render(const FrameScene& scene, const ViewSettings& view) {
    std::vector<std::uint8_t> rgba;
    std::string err;
    EXPECT_TRUE(renderer_->render(scene, view, kWidth, kHeight, &rgba, &err)) << err;
    EXPECT_EQ(renderer_->gl_error(), 0u);
    return rgba;
  }
  const FrameLayout& layout() const { return renderer_->last_layout(); }

  static constexpr int kWidth = 1280, kHeight = 720;
  static inline cli::OffscreenRenderer* renderer_ = nullptr;
};

}  // namespace sph::render::test

// The frame's chrome colours (palette.h): the standard dark-grey theme, and with
// ViewSettings::high_contrast (sph-gui's and sph run's --high-contrast) a black frame and plot with white
// labels: the title's text pixels, the plot's fill and the frame around it take the chosen theme's colours.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class Palette : public OffscreenTest {
 protected:
  /// Pixels of rect r within `tol` of colour c.
  static int pixels_near(const std::vector<std::uint8_t>& rgba, const PixelRect& r, Rgba c, int tol) {
    return count_colour(rgba, kWidth, r, to_pixel8(c), tol);
  }
};

TEST_F(Palette, HighContrastIsWhiteOnBlackAroundTheData) {
  const Snapshot s = sod_profile_1d(200);
  for (const bool high : {false, true}) {
    ViewSettings v;
    v.high_contrast = high;
    const auto rgba = render(s, v);
    const palette::Chrome& want = palette::chrome(high);
    const palette::Chrome& other = palette::chrome(!high);
    const PixelRect title = layout().title, plot = layout().plot;
    // a corner of the plot away from the dots and the curve (Sod's low right state sits at the bottom)
    const PixelRect fill{plot.x + 0.75f * plot.w, plot.y + 0.2f * plot.h, 0.1f * plot.w, 0.1f * plot.h};
    const float area = fill.w * fill.h;
    EXPECT_GT(pixels_near(rgba, fill, want.plot_fill, 2), 0.6f * area) << high;
    EXPECT_EQ(pixels_near(rgba, fill, other.plot_fill, 2), 0) << high;
    // the title row: background and text in the theme's colours, none of the other theme's text
    EXPECT_GT(pixels_near(rgba, title, want.background, 2), 0.5f * title.w * title.h) << high;
    EXPECT_GT(pixels_near(rgba, title, want.text, 8), 20) << high;
    EXPECT_EQ(pixels_near(rgba, title, other.text, 2), 0) << high;
  }
}

}  // namespace
}  // namespace sph::render::test

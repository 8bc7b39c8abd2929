// The Barnes-Hut overlay (Snapshot::tree_cells): cells used whole drawn sky blue and leaves amber along
// their edges, over the particles, with the probed particle marked; nothing without cells, without a
// probe, or with the overlay switched off.
#include <gtest/gtest.h>

#include "palette.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class RenderTreeOverlay : public OffscreenTest {
 protected:
  static Snapshot with_cells() {
    Snapshot s = lattice_2d(20, 10);
    s.tree_cells = {{{0.5f, 0.5f, 0.f}, 0.25f, true}, {{1.5f, 0.5f, 0.f}, 0.125f, false}};
    s.tree_probe = 0;
    return s;
  }
  bool near(const std::vector<std::uint8_t>& rgba, float wx, float wy, Rgba c) const {
    float px = 0, py = 0;
    EXPECT_TRUE(layout().to_pixel(wx, wy, 0.f, &px, &py));
    return colour_near(rgba, kWidth, kHeight, px, py, to_pixel8(c), 1, 12);
  }
  // Midpoints of the four edges of the square centred at (cx, cy) with half side h.
  int edges_in(const std::vector<std::uint8_t>& rgba, float cx, float cy, float h, Rgba c) const {
    return near(rgba, cx - h, cy, c) + near(rgba, cx + h, cy, c) + near(rgba, cx, cy - h, c) + near(rgba, cx, cy + h, c);
  }
};

TEST_F(RenderTreeOverlay, WholeCellsBlueLeavesAmberAlongTheirEdges) {
  const auto rgba = render(with_cells(), ViewSettings{});
  EXPECT_EQ(edges_in(rgba, 0.5f, 0.5f, 0.25f, palette::kOutlines[2]), 4);
  EXPECT_EQ(edges_in(rgba, 1.5f, 0.5f, 0.125f, palette::kOutlines[1]), 4);
  EXPECT_EQ(edges_in(rgba, 1.5f, 0.5f, 0.125f, palette::kOutlines[2]), 0);  // a leaf is not drawn as whole
  EXPECT_FALSE(near(rgba, 0.5f, 0.5f, palette::kOutlines[2]));  // inside a cell: the particles
}

TEST_F(RenderTreeOverlay, NothingWithoutCellsProbeOrWhenSwitchedOff) {
  Snapshot no_probe = with_cells();
  no_probe.tree_probe = -1;
  ViewSettings off;
  off.show_tree = false;
  for (const auto& rgba : {render(no_probe, ViewSettings{}), render(with_cells(), off)}) {
    EXPECT_EQ(edges_in(rgba, 0.5f, 0.5f, 0.25f, palette::kOutlines[2]), 0);
    EXPECT_EQ(edges_in(rgba, 1.5f, 0.5f, 0.125f, palette::kOutlines[1]), 0);
  }
}

}  // namespace
}  // namespace sph::render::test

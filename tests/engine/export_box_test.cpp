// The box of the SWIFT/GADGET layout (io/export_box.h): an open scene keeps one frame while its particles
// move, so the snapshots of a run line up (yt time series); every particle stays inside [0, BoxSize).
#include "io/export_box.h"

#include <gtest/gtest.h>

namespace sph {
namespace {

void expect_inside(const World& w, const ExportBox& b) {
  const Particles& p = w.particles();
  for (int k = 0; k < p.dim(); ++k)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double x = p.x[k][i] + b.shift[k];
      ASSERT_GE(x, 0.0) << "axis " << k << " particle " << i;
      ASSERT_LT(x, b.size[k]) << "axis " << k << " particle " << i;
    }
}

TEST(ExportBox, AnOpenSceneKeepsOneFrameWhileItsParticlesMove) {
  RunConfig cfg = RunConfig::from_scene("evrard");
  cfg.set("scene.n", "300", "test");
  World w(cfg);
  const ExportBox first = export_box(w);
  EXPECT_FALSE(first.periodic);
  expect_inside(w, first);
  // evrard's domain is [-1.5, 1.5]^3: four times its side, centred on it
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(first.size[k], 12.0);
    EXPECT_DOUBLE_EQ(first.shift[k], 6.0);
  }
  for (int s = 0; s < 5; ++s) w.step();
  const ExportBox later = export_box(w);
  EXPECT_EQ(later.size, first.size);  // bit for bit: the frame does not follow the particles
  EXPECT_EQ(later.shift, first.shift);
  expect_inside(w, later);
}

TEST(ExportBox, APeriodicBoxIsTheDomainAtTheOrigin) {
  const World w(RunConfig::from_scene("box_lattice"));
  const ExportBox b = export_box(w);
  EXPECT_TRUE(b.periodic);
  for (int k = 0; k < w.particles().dim(); ++k) {
    EXPECT_DOUBLE_EQ(b.size[k], w.domain().length(k));
    EXPECT_DOUBLE_EQ(b.shift[k], -w.domain().lo[k]);
  }
  expect_inside(w, b);
}

}  // namespace
}  // namespace sph

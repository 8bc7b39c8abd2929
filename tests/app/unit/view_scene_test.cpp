// What the particle view is given from a stepper frame: run B and the labels when comparing (the
// overridden keys with each run's values), both runs' reference errors, and the inspected particle with
// its neighbours weighted by W relative to the largest.
#include <gtest/gtest.h>

#include "view_scene.h"

namespace sph::gui {
namespace {

TEST(ViewScene, OneRunOrTwoWithTheirLabelsAndErrors) {
  StepperFrame f;
  f.config = RunConfig::from_scene("sod");
  f.ref_columns = {{"count", "", false}, {"L1_rho", "", true}};
  f.ref_values = {400, 0.003};
  render::FrameScene one = view_scene(f);
  EXPECT_EQ(one.a, &f.snapshot);
  EXPECT_EQ(one.b, nullptr);
  EXPECT_LT(one.highlight.index, 0);
  f.comparing = true;
  f.compare.overrides = {"kernel.type=M6"};
  f.compare.config = f.config;
  f.compare.config.set("kernel.type", "M6", "test");
  f.compare.ref_values = {400, 0.0028};
  const render::FrameScene two = view_scene(f);
  EXPECT_EQ(two.b, &f.compare.snapshot);
  EXPECT_EQ(two.label_a, "A: kernel.type=M4");
  EXPECT_EQ(two.label_b, "B: kernel.type=M6");
  ASSERT_EQ(two.errors_b.size(), 2u);
  EXPECT_EQ(two.errors_b[1], (std::pair<std::string, double>{"L1_rho", 0.0028}));
}

TEST(ViewScene, ASweepLabelsEachRunWithItsValue) {
  StepperFrame f;
  f.config = RunConfig::from_scene("sod");  // kernel.eta = 0: M4's default, 1.2
  f.ref_columns = {{"count", "", false}, {"L1_rho", "", true}};
  f.ref_values = {400, 0.003};
  f.sweep_key = "kernel.eta";
  for (const char* v : {"1", "1.5"}) {
    CompareFrame r;
    r.overrides = {std::string("kernel.eta=") + v};
    r.config = f.config;
    r.config.set("kernel.eta", v, "test");
    r.ref_values = {400, v[0] == '1' && v[1] == 0 ? 0.0027 : 0.0036};
    f.sweep.push_back(r);
  }
  const render::FrameScene s = view_scene(f);
  EXPECT_EQ(s.b, nullptr);
  EXPECT_EQ(s.sweep_key, "kernel.eta");
  EXPECT_EQ(s.label_a, "kernel.eta=1.2 (default, A)");
  EXPECT_EQ(s.value_a, "1.2 (default, A)");
  ASSERT_EQ(s.sweep.size(), 2u);
  EXPECT_EQ(s.sweep[0].snap, &f.sweep[0].snapshot);
  EXPECT_EQ(s.sweep[0].label, "kernel.eta=1");
  EXPECT_EQ(s.sweep[1].value, "1.5");
  EXPECT_EQ(s.sweep[0].errors[1], (std::pair<std::string, double>{"L1_rho", 0.0027}));
  EXPECT_EQ(s.sweep[1].errors[1], (std::pair<std::string, double>{"L1_rho", 0.0036}));
}

TEST(ViewScene, HighlightWeightsAreRelativeToTheLargestW) {
  Inspection in;
  in.id = 7;
  InspectNeighbour a, b;
  a.id = 6;
  a.W = 2.0;
  b.id = 9;
  b.W = 0.5;
  in.neighbour_list = {a, b};
  const render::Highlight h = highlight_of(in);
  EXPECT_EQ(h.index, 7);
  ASSERT_EQ(h.neighbours.size(), 2u);
  EXPECT_EQ(h.neighbours[0], (std::pair<std::uint32_t, float>{6, 1.f}));
  EXPECT_EQ(h.neighbours[1], (std::pair<std::uint32_t, float>{9, 0.25f}));
}

}  // namespace
}  // namespace sph::gui

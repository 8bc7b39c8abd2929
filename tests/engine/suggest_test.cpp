// "Did you mean": edit distances and the nearest key, scene or flag (sph/suggest.h).
#include "sph/suggest.h"

#include <gtest/gtest.h>

namespace sph {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // the textbook example
  EXPECT_EQ(edit_distance("n_left", "n_lfet"), 1u);   // one adjacent swap
  EXPECT_EQ(edit_distance("vtu", "vtk"), 1u);
  EXPECT_EQ(edit_distance("abc", "abc"), 0u);
}

TEST(Nearest, FindsTheKeyATypoMeant) {
  const std::vector<std::string> keys = {"scene.n_left", "scene.rho_l", "kernel.eta", "visc.alpha", "time.t_end"};
  EXPECT_EQ(nearest("scene.n_lef", keys), "scene.n_left");
  EXPECT_EQ(nearest("n_left", keys), "scene.n_left");  // the name without its group
  EXPECT_EQ(nearest("kernal.eta", keys), "kernel.eta");
  EXPECT_EQ(nearest("VISC.ALPHA", keys), "visc.alpha");  // case does not matter
  EXPECT_EQ(nearest("time.t_ned", keys), "time.t_end");
  // the start of a name beats a one-letter edit ("scene.n" is not "scene.E")
  EXPECT_EQ(nearest("scene.n", {"scene.E", "scene.n_side", "scene.half"}), "scene.n_side");
  EXPECT_EQ(nearest("scene.rho", keys), "scene.rho_l");
}

TEST(Nearest, SaysNothingWhenNothingIsClose) {
  const std::vector<std::string> scenes = {"sod", "lax", "toro1", "kepler"};
  EXPECT_EQ(nearest("sodd", scenes), "sod");
  EXPECT_EQ(nearest("elliptical", scenes), "");
  EXPECT_EQ(nearest("", scenes), "");
  EXPECT_EQ(did_you_mean("keplr", scenes), " (did you mean kepler?)");
  EXPECT_EQ(did_you_mean("zzzzzz", scenes), "");
}

}  // namespace
}  // namespace sph

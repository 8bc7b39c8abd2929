// The off-screen backends behind the context seam (offscreen_context.h): SPH_GL picks the one the whole
// suite runs on, the context says which it is, and OSMesa and EGL in one process draw the same frame.
#include "offscreen_context.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "frame_recorder.h"
#include "synthetic_snapshots.h"

namespace sph::cli {
namespace {

TEST(OffscreenContext, TheRequestedBackendIsTheOneThatRuns) {
  const char* env = std::getenv("SPH_GL");
  const std::string want = env ? env : "auto";
  std::string err;
  auto r = OffscreenRenderer::create(&err);  // the backend SPH_GL names
  ASSERT_NE(r, nullptr) << err;
  const std::string what = r->description();
  if (want == "egl") {
    EXPECT_EQ(what.rfind("EGL (", 0), 0u) << what;
  }
  if (want == "osmesa") {
    EXPECT_EQ(what.rfind("OSMesa", 0), 0u) << what;
  }
  EXPECT_NE(what.find("OpenGL"), std::string::npos) << what;
}

TEST(OffscreenContext, ParsesTheFlagAndNamesTheBuiltBackends) {
  GlBackend b = GlBackend::Auto;
  EXPECT_TRUE(parse_gl_backend("egl", &b));
  EXPECT_EQ(b, GlBackend::Egl);
  EXPECT_TRUE(parse_gl_backend("osmesa", &b));
  EXPECT_EQ(b, GlBackend::OSMesa);
  EXPECT_FALSE(parse_gl_backend("vulkan", &b));
  EXPECT_FALSE(built_gl_backends().empty());
}

TEST(OffscreenContext, BothBackendsDrawTheSameFrame) {
  const std::string built = built_gl_backends();
  if (built.find("osmesa") == std::string::npos || built.find("egl") == std::string::npos)
    GTEST_SKIP() << "this build has only " << built;
  const Snapshot snap = render::test::lattice_2d(20, 10);
  std::vector<std::uint8_t> a, b;
  std::string err;
  auto osmesa = OffscreenRenderer::create(&err, GlBackend::OSMesa);
  ASSERT_NE(osmesa, nullptr) << err;
  auto egl = OffscreenRenderer::create(&err, GlBackend::Egl);
  ASSERT_NE(egl, nullptr) << err;
  ASSERT_TRUE(osmesa->render(snap, render::ViewSettings{}, 320, 180, &a, &err)) << err;
  ASSERT_TRUE(egl->render(snap, render::ViewSettings{}, 320, 180, &b, &err)) << err;
  ASSERT_EQ(a.size(), b.size());
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  EXPECT_LE(worst, 2) << "largest channel difference between OSMesa and EGL (llvmpipe both)";
  EXPECT_EQ(osmesa->gl_error(), 0u);
  EXPECT_EQ(egl->gl_error(), 0u);
}

}  // namespace
}  // namespace sph::cli

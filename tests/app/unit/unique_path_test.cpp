// Screenshot names never overwrite an earlier file (app/gui/unique_path.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "unique_path.h"

namespace sph::gui {
namespace {

TEST(UniquePath, SecondAndThirdShotsAtTheSameStepGetNewNames) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sph_unique_path_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string stem = (dir / "sph-gui_sod_step12").string();
  const std::string first = unique_path(stem, ".png");
  EXPECT_EQ(first, stem + ".png");
  std::ofstream(first) << "x";
  const std::string second = unique_path(stem, ".png");
  EXPECT_EQ(second, stem + "_2.png");
  std::ofstream(second) << "x";
  EXPECT_EQ(unique_path(stem, ".png"), stem + "_3.png");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sph::gui

// The recent-files list: newest first, no duplicates, at most 10, kept in DIR/recent.json across runs; a
// malformed file gives an empty list and a message naming the file and key.
#include "recent_files.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace sph::gui {
namespace {

std::filesystem::path scratch(const char* name) {
  const auto d = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(d);
  return d;
}

TEST(RecentFiles, NewestFirstWithoutDuplicatesAndKept) {
  const auto dir = scratch("sph_recent_test");
  {
    RecentFiles r(dir.string());
    EXPECT_TRUE(r.files().empty());
    EXPECT_TRUE(r.error().empty());
    EXPECT_TRUE(r.add("/a/one.json"));
    EXPECT_TRUE(r.add("/a/two.json"));
    EXPECT_TRUE(r.add("/a/one.json"));
    EXPECT_EQ(r.files(), (std::vector<std::string>{"/a/one.json", "/a/two.json"}));
  }
  const RecentFiles again(dir.string());  // read back from dir/recent.json
  EXPECT_EQ(again.files(), (std::vector<std::string>{"/a/one.json", "/a/two.json"}));
  EXPECT_EQ(again.file(), (dir / "recent.json").string());
  std::filesystem::remove_all(dir);
}

TEST(RecentFiles, KeepsTheTenNewestAndMakesPathsAbsolute) {
  const auto dir = scratch("sph_recent_test_ten");
  RecentFiles r(dir.string());
  for (int i = 0; i < 12; ++i) r.add("/s/" + std::to_string(i) + ".json");
  ASSERT_EQ(r.files().size(), RecentFiles::kMax);
  EXPECT_EQ(r.files().front(), "/s/11.json");
  EXPECT_EQ(r.files().back(), "/s/2.json");
  r.add("relative.json");
  EXPECT_TRUE(std::filesystem::path(r.files().front()).is_absolute());
  std::filesystem::remove_all(dir);
}

TEST(RecentFiles, MalformedFileStartsEmptyNamingIt) {
  const auto dir = scratch("sph_recent_test_bad");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "recent.json") << R"({"recent": 3})";
  RecentFiles r(dir.string());
  EXPECT_TRUE(r.files().empty());
  EXPECT_NE(r.error().find((dir / "recent.json").string()), std::string::npos);
  EXPECT_NE(r.error().find("'recent'"), std::string::npos);
  EXPECT_TRUE(r.add("/x.json"));  // and is replaced on the next add
  EXPECT_EQ(RecentFiles(dir.string()).files(), std::vector<std::string>{"/x.json"});
  std::filesystem::remove_all(dir);
}

TEST(RecentFiles, DefaultFolderFollowsXdgConfigHome) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(default_config_dir(), "/tmp/xdg-test/sph-sandbox");
  unsetenv("XDG_CONFIG_HOME");
  setenv("HOME", std::getenv("HOME") ? std::getenv("HOME") : "/root", 1);
  EXPECT_EQ(default_config_dir(), std::string(std::getenv("HOME")) + "/.config/sph-sandbox");
  if (old) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
}

}  // namespace
}  // namespace sph::gui

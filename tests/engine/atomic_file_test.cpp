// The atomic writers (sph/atomic_file.h) and the output manifest: complete files or none, never a
// partial file or a leftover temporary, including when a write fails midway (fault injection).
#include "sph/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "sph/output_manifest.h"

namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// A fresh empty folder per test.
struct AtomicFile : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("sph_atomic_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override {
    sph::testing::set_write_function(nullptr);
    fs::remove_all(dir);
  }
};

// A disk that fills up after 100 bytes: the first call writes at most 100 bytes, later calls fail ENOSPC.
std::size_t g_written = 0;
ssize_t full_after_100(int fd, const void* data, std::size_t size) {
  if (g_written >= 100) {
    errno = ENOSPC;
    return -1;
  }
  const std::size_t n = std::min<std::size_t>(size, 100 - g_written);
  g_written += n;
  return ::write(fd, data, n);
}

// Room for small files only: a write of 500 bytes or more fails after 100 of them (ENOSPC).
ssize_t full_for_big_files(int fd, const void* data, std::size_t size) {
  if (size < 500) return ::write(fd, data, size);
  if (::write(fd, data, 100) != 100) return -1;
  errno = ENOSPC;
  return -1;
}

}  // namespace

TEST_F(AtomicFile, WritesWholeFileWithItsStampAndNoTemporary) {
  sph::FileStamp stamp;
  EXPECT_EQ(sph::write_file_atomic(dir / "a.txt", "hello", &stamp), "");
  EXPECT_EQ(read_all(dir / "a.txt"), "hello");
  EXPECT_EQ(stamp.bytes, 5u);
  EXPECT_EQ(stamp.crc32, 0x3610a686u);  // CRC-32 of "hello" (as zlib, gzip, PNG)
  EXPECT_EQ(listing(dir), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicFile, WriteFailingMidwayLeavesNoFileAndNoTemporary) {
  g_written = 0;
  sph::testing::set_write_function(full_after_100);
  const std::string big(1000, 'x');
  const std::string err = sph::write_file_atomic(dir / "big.csv", big);
  EXPECT_NE(err.find((dir / "big.csv").string()), std::string::npos) << err;  // names the file
  EXPECT_NE(err.find(std::strerror(ENOSPC)), std::string::npos) << err;
  EXPECT_EQ(g_written, 100u);  // it did fail midway, after a partial write
  EXPECT_TRUE(listing(dir).empty());
}

TEST_F(AtomicFile, FailedRewriteKeepsThePreviousCompleteFile) {
  ASSERT_EQ(sph::write_file_atomic(dir / "m.json", "old content"), "");
  g_written = 0;
  sph::testing::set_write_function(full_after_100);
  EXPECT_NE(sph::write_file_atomic(dir / "m.json", std::string(500, 'n')), "");
  EXPECT_EQ(read_all(dir / "m.json"), "old content");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"m.json"});
}

TEST_F(AtomicFile, VanishedFolderIsReportedByName) {
  const fs::path gone = dir / "gone" / "x.csv";
  const std::string err = sph::write_file_atomic(gone, "data");
  EXPECT_NE(err.find(gone.string()), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "gone"));
}

TEST_F(AtomicFile, FullDeviceIsWrittenInPlaceAndFails) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const std::string err = sph::write_file_atomic("/dev/full", "data");
  EXPECT_NE(err.find("/dev/full"), std::string::npos) << err;
  EXPECT_NE(err.find(std::strerror(ENOSPC)), std::string::npos) << err;
}

TEST_F(AtomicFile, GrowingFileIsPartUntilFinished) {
  sph::GrowingFile g;
  ASSERT_EQ(g.open(dir / "diag.csv"), "");
  ASSERT_EQ(g.append("a,b\n"), "");
  ASSERT_EQ(g.append("1,2\n"), "");
  ASSERT_EQ(g.flush(), "");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"diag.csv.part"});
  EXPECT_EQ(read_all(dir / "diag.csv.part"), "a,b\n1,2\n");
  EXPECT_EQ(g.stamp().bytes, 8u);
  EXPECT_EQ(g.stamp().crc32, sph::crc32_of("a,b\n1,2\n"));
  ASSERT_EQ(g.finish(), "");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"diag.csv"});
  EXPECT_EQ(read_all(dir / "diag.csv"), "a,b\n1,2\n");
}

TEST_F(AtomicFile, GrowingFileFailingMidwayLeavesNothing) {
  sph::GrowingFile g;
  ASSERT_EQ(g.open(dir / "diag.csv"), "");
  g_written = 0;
  sph::testing::set_write_function(full_after_100);
  ASSERT_EQ(g.append(std::string(80, 'r')), "");  // buffered
  ASSERT_EQ(g.append(std::string(80, 'r')), "");
  const std::string err = g.finish();
  EXPECT_NE(err.find((dir / "diag.csv").string()), std::string::npos) << err;
  EXPECT_TRUE(listing(dir).empty());
}

TEST_F(AtomicFile, AbandonRemovesThePart) {
  sph::GrowingFile g;
  ASSERT_EQ(g.open(dir / "errors.csv"), "");
  ASSERT_EQ(g.append("x\n"), "");
  g.abandon();
  EXPECT_TRUE(listing(dir).empty());
}

TEST_F(AtomicFile, ManifestListsCompletedFilesOnly) {
  sph::OutputManifest m(dir);
  ASSERT_EQ(m.write("scene.json", "{}"), "");
  ASSERT_EQ(m.write("particles_00000.csv", "id\n0\n"), "");
  g_written = 0;
  sph::testing::set_write_function(full_after_100);
  EXPECT_NE(m.write("particles_00001.csv", std::string(1000, 'p')), "");
  sph::testing::set_write_function(nullptr);
  sph::testing::set_write_function(full_for_big_files);  // a rewrite that fails: unlisted, the old file kept
  EXPECT_NE(m.write("scene.json", std::string(1000, 's')), "");
  EXPECT_EQ(read_all(dir / "scene.json"), "{}");
  sph::testing::set_write_function(nullptr);
  auto j = nlohmann::json::parse(read_all(dir / "manifest.json"));
  ASSERT_EQ(j["files"].size(), 1u);
  EXPECT_EQ(j["files"][0]["name"], "particles_00000.csv");
  ASSERT_EQ(m.write("scene.json", "{\"a\":1}"), "");  // rewritten: listed again, new stamp
  j = nlohmann::json::parse(read_all(dir / "manifest.json"));
  ASSERT_EQ(j["files"].size(), 2u);
  EXPECT_EQ(j["files"][1]["name"], "scene.json");
  EXPECT_EQ(j["files"][1]["bytes"], 7);
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", static_cast<unsigned>(sph::crc32_of("{\"a\":1}")));
  EXPECT_EQ(j["files"][1]["crc32"], crc);
  EXPECT_EQ(j["files"][0]["name"], "particles_00000.csv");
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"manifest.json", "particles_00000.csv", "scene.json"}));
}

// FrameRecorder: option validation, numbered PNG files of the right size, frame cadence, the
// colour-by check, and the ffmpeg step.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "frame_recorder.h"
#include "synthetic_snapshots.h"

namespace sph::cli {
namespace {

namespace fs = std::filesystem;

struct PngHeader {
  bool ok = false;
  std::uint32_t width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

PngHeader read_png_header(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  unsigned char b[26] = {};
  in.read(reinterpret_cast<char*>(b), sizeof b);
  PngHeader h;
  const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || std::memcmp(b, sig, 8) != 0 || std::memcmp(b + 12, "IHDR", 4) != 0) return h;
  auto be32 = [&](int i) { return (std::uint32_t(b[i]) << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3]; };
  h.ok = true;
  h.width = be32(16);
  h.height = be32(20);
  h.bit_depth = b[24];
  h.colour_type = b[25];
  return h;
}

class FrameRecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sph_frames_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  FrameOptions options() const {
    FrameOptions o;
    o.dir = (dir_ / "frames").string();
    o.width = 320;
    o.height = 180;
    return o;
  }
  fs::path dir_;
};

TEST_F(FrameRecorderTest, ValidationNamesTheFlag) {
  std::string err;
  FrameOptions o = options();
  o.width = 321;
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--size 321x180"), std::string::npos) << err;
  EXPECT_NE(err.find("even"), std::string::npos) << err;

  o = options();
  o.height = 0;
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--size"), std::string::npos) << err;

  o = options();
  o.cmap = "jet";
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--cmap"), std::string::npos) << err;
  EXPECT_NE(err.find("viridis, magma, cividis, coolwarm"), std::string::npos) << err;

  o = options();
  o.every = 0.0;
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--every"), std::string::npos) << err;

  o = options();
  o.auto_range = false;
  o.range_min = 2.f;
  o.range_max = 1.f;
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--range"), std::string::npos) << err;

  o = options();
  o.dir.clear();
  EXPECT_EQ(FrameRecorder::create(o, &err), nullptr);
  EXPECT_NE(err.find("--frames"), std::string::npos) << err;
}

TEST_F(FrameRecorderTest, ProfileAxisIsXYROrOff) {
  std::string err;
  FrameOptions o = options();
  for (const char* bad : {"z", "", "X", "yes"}) {
    o.profile_axis = bad;
    EXPECT_EQ(FrameRecorder::create(o, &err), nullptr) << bad;
    EXPECT_NE(err.find("--profile-axis"), std::string::npos) << err;
    EXPECT_NE(err.find("x, y, r or off"), std::string::npos) << err;
  }
  for (auto [name, axis] : {std::pair{"off", -1}, {"x", 0}, {"y", 1}, {"r", 3}}) {
    o.profile_axis = name;
    auto rec = FrameRecorder::create(o, &err);
    ASSERT_NE(rec, nullptr) << err;
    EXPECT_EQ(rec->view().profile_axis, axis) << name;
  }
  EXPECT_EQ(FrameOptions{}.profile_axis, "off");
}

TEST_F(FrameRecorderTest, WritesNumberedPngsOfTheRequestedSize) {
  std::string err;
  auto rec = FrameRecorder::create(options(), &err);
  ASSERT_NE(rec, nullptr) << err;
  EXPECT_TRUE(fs::is_directory(dir_ / "frames"));  // created, with its parent
  Snapshot s = render::test::lattice_2d(20, 10);
  for (int i = 0; i < 3; ++i) {
    s.t = 0.1 * i;
    ASSERT_TRUE(rec->write_frame(s, &err)) << err;
  }
  EXPECT_EQ(rec->frames_written(), 3);
  ASSERT_TRUE(rec->flush(&err)) << err;  // PNGs are written in the background
  for (const char* name : {"frame_00000.png", "frame_00001.png", "frame_00002.png"}) {
    const PngHeader h = read_png_header(dir_ / "frames" / name);
    ASSERT_TRUE(h.ok) << name;
    EXPECT_EQ(h.width, 320u);
    EXPECT_EQ(h.height, 180u);
    EXPECT_EQ(h.bit_depth, 8);
    EXPECT_EQ(h.colour_type, 2);  // RGB
  }
  EXPECT_FALSE(fs::exists(dir_ / "frames" / "frame_00003.png"));
}

TEST_F(FrameRecorderTest, WriteErrorsAreReported) {
  std::string err;
  auto rec = FrameRecorder::create(options(), &err);
  ASSERT_NE(rec, nullptr) << err;
  fs::remove_all(dir_ / "frames");  // the directory vanishes under the recorder
  const Snapshot s = render::test::lattice_2d(4, 4);
  ASSERT_TRUE(rec->write_frame(s, &err)) << err;  // queued
  EXPECT_FALSE(rec->flush(&err));
  EXPECT_NE(err.find("frame_00000.png"), std::string::npos) << err;
}

TEST_F(FrameRecorderTest, UnknownColourFieldIsReportedWithTheAvailableOnes) {
  FrameOptions o = options();
  o.color_by = "vorticity";
  std::string err;
  auto rec = FrameRecorder::create(o, &err);
  ASSERT_NE(rec, nullptr) << err;
  EXPECT_FALSE(rec->write_frame(render::test::lattice_2d(4, 4), &err));
  EXPECT_NE(err.find("'vorticity'"), std::string::npos) << err;
  EXPECT_NE(err.find("available: rho, p"), std::string::npos) << err;
  EXPECT_NE(err.find("--color-by"), std::string::npos) << err;
  EXPECT_EQ(rec->frames_written(), 0);
}

TEST_F(FrameRecorderTest, FramesAreDueOncePerInterval) {
  std::string err;
  auto rec = FrameRecorder::create(options(), &err);  // every = 0.1
  ASSERT_NE(rec, nullptr) << err;
  Snapshot s = render::test::lattice_2d(4, 4);
  EXPECT_TRUE(rec->frame_due(0.0));
  s.t = 0.0;
  ASSERT_TRUE(rec->write_frame(s, &err)) << err;
  EXPECT_FALSE(rec->frame_due(0.05));
  EXPECT_TRUE(rec->frame_due(0.1 - 1e-13));  // rounding of t = n * dt does not skip a frame
  s.t = 0.35;  // a big step: the next frame is due at 0.4, not at every step from here
  ASSERT_TRUE(rec->write_frame(s, &err)) << err;
  EXPECT_FALSE(rec->frame_due(0.36));
  EXPECT_TRUE(rec->frame_due(0.4));
}

TEST_F(FrameRecorderTest, FfmpegCommandAndVideo) {
  FrameOptions o = options();
  o.video = (dir_ / "movie.mp4").string();
  o.fps = 24;
  std::string err;
  auto rec = FrameRecorder::create(o, &err);
  ASSERT_NE(rec, nullptr) << err;
  const std::string cmd = rec->ffmpeg_command();
  EXPECT_NE(cmd.find("ffmpeg "), std::string::npos);
  EXPECT_NE(cmd.find("-framerate 24"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("frame_%05d.png"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("-pix_fmt yuv420p"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("movie.mp4'"), std::string::npos) << cmd;

  EXPECT_FALSE(rec->make_video(&err));  // no frames yet
  EXPECT_NE(err.find("no frames"), std::string::npos) << err;

  Snapshot s = render::test::lattice_2d(8, 4);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(rec->write_frame(s, &err)) << err;

  // Without ffmpeg on PATH: a clear message that names the command to run later.
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (dir_ / "empty_bin").c_str(), 1);
  EXPECT_FALSE(rec->make_video(&err));
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_NE(err.find("ffmpeg is not installed"), std::string::npos) << err;
  EXPECT_NE(err.find("frame_%05d.png"), std::string::npos) << err;

  bool have_ffmpeg = false;
  for (const char* d : {"/usr/bin/ffmpeg", "/usr/local/bin/ffmpeg"}) have_ffmpeg |= ::access(d, X_OK) == 0;
  if (!have_ffmpeg) GTEST_SKIP() << "ffmpeg not installed: video encoding not exercised";
  ASSERT_TRUE(rec->make_video(&err)) << err;
  EXPECT_GT(fs::file_size(o.video), 0u);
}

TEST_F(FrameRecorderTest, NoVideoRequestedIsNotAnError) {
  std::string err;
  auto rec = FrameRecorder::create(options(), &err);
  ASSERT_NE(rec, nullptr) << err;
  EXPECT_TRUE(rec->make_video(&err));
}

TEST(RenderSnapshotRgba, OneOffRenderingWorks) {
  std::vector<std::uint8_t> rgba;
  std::string err;
  ASSERT_TRUE(render_snapshot_rgba(render::test::sod_profile_1d(100), render::ViewSettings{}, 200, 100, &rgba, &err))
      << err;
  EXPECT_EQ(rgba.size(), 200u * 100u * 4u);
}

}  // namespace
}  // namespace sph::cli

// The checkpoint container (sph/checkpoint.h): a round trip keeps every byte of every section, and each
// kind of damage (empty, truncated, a flipped byte, another version, a foreign file, a directory, a
// missing file) is refused with a CheckpointError naming the file.
#include "sph/checkpoint.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace sph {
namespace {

Checkpoint sample() {
  Checkpoint c;
  c.config_json = R"({"scene":"sod"})";
  c.run_options = "options";
  c.world = std::string("\0\1\2\xff binary", 11);
  for (int i = 0; i < 1000; ++i) c.world.push_back(static_cast<char>(i * 37));
  c.extra = "";
  return c;
}

/// The message of the CheckpointError decode throws for `bytes` ("" if it throws none).
std::string refusal(const std::string& bytes) {
  try {
    decode_checkpoint(bytes, "/x/checkpoint.sph");
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFile, RoundTripKeepsEverySection) {
  const Checkpoint c = sample();
  const Checkpoint d = decode_checkpoint(encode_checkpoint(c), "mem");
  EXPECT_EQ(d.config_json, c.config_json);
  EXPECT_EQ(d.run_options, c.run_options);
  EXPECT_EQ(d.world, c.world);
  EXPECT_EQ(d.extra, c.extra);
}

TEST(CheckpointFile, EveryTruncationIsRefused) {
  const std::string bytes = encode_checkpoint(sample());
  for (std::size_t n = 0; n < bytes.size(); n += 7) {
    const std::string why = refusal(bytes.substr(0, n));
    EXPECT_NE(why.find("/x/checkpoint.sph"), std::string::npos) << "cut at " << n << ": " << why;
  }
}

TEST(CheckpointFile, EveryFlippedByteIsRefused) {
  const std::string bytes = encode_checkpoint(sample());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    EXPECT_NE(refusal(bad), "") << "byte " << i;
  }
  std::string bad = bytes;
  bad[bytes.size() / 2] ^= 1;
  EXPECT_NE(refusal(bad).find("checksum"), std::string::npos);
}

TEST(CheckpointFile, OtherVersionEmptyAndForeignFilesAreNamed) {
  std::string other = encode_checkpoint(sample());
  other[8] = static_cast<char>(kCheckpointVersion + 1);  // the version follows the 8-byte magic
  const std::string named = "version " + std::to_string(kCheckpointVersion + 1);
  EXPECT_NE(refusal(other).find(named), std::string::npos) << refusal(other);
  EXPECT_NE(refusal("").find("empty"), std::string::npos);
  EXPECT_NE(refusal("id,x,y,z\n1,2,3,4\n").find("not a checkpoint"), std::string::npos);
  EXPECT_NE(refusal(encode_checkpoint(sample()) + "x"), "");  // trailing bytes
}

TEST(CheckpointFile, WriteReadAndRefuseFiles) {
  const auto dir = std::filesystem::temp_directory_path() / ("sph_ck_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "checkpoint.sph").string();
  ASSERT_EQ(write_checkpoint(path, sample()), "");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  EXPECT_EQ(read_checkpoint(path).world, sample().world);
  EXPECT_THROW(read_checkpoint(dir.string()), CheckpointError);               // a directory
  EXPECT_THROW(read_checkpoint((dir / "missing.sph").string()), CheckpointError);  // no such file
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 1);
  try {
    read_checkpoint(path);
    ADD_FAILURE() << "a truncated file was read";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sph

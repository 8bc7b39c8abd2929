// The checkpoint container (sph/checkpoint.h): sections, size, checksum and end marker; whole-file
// writes through a temporary name.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/byte_stream.h"
#include "sph/checkpoint.h"

namespace sph {
namespace {

constexpr char kMagic[9] = "SPHCHKPT";
constexpr char kEnd[9] = "ENDCHKPT";
constexpr std::size_t kHeader = 8 + 4 + 4 + 8;  // magic, version, reserved, size
constexpr std::size_t kTrailer = 8 + 8;         // checksum, end marker

/// Writes all of `bytes` to fd; false on any error.
bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

std::uint64_t fnv1a64(const char* data, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string encode_checkpoint(const Checkpoint& c) {
  ByteWriter w;
  for (int i = 0; i < 8; ++i) w.put<char>(kMagic[i]);
  w.put<std::uint32_t>(kCheckpointVersion);
  w.put<std::uint32_t>(0);
  const std::uint64_t size = kHeader + 4 * 8 + c.config_json.size() + c.run_options.size() + c.world.size() +
                             c.extra.size() + kTrailer;
  w.put<std::uint64_t>(size);
  for (const std::string* s : {&c.config_json, &c.run_options, &c.world, &c.extra}) w.put_string(*s);
  std::string out = w.take();
  ByteWriter tail;
  tail.put<std::uint64_t>(fnv1a64(out.data(), out.size()));
  for (int i = 0; i < 8; ++i) tail.put<char>(kEnd[i]);
  out += tail.bytes();
  return out;
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& path) {
  const std::string what = "checkpoint " + path;
  if (bytes.empty()) throw CheckpointError(what + ": the file is empty");
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
    throw CheckpointError(what + ": not a checkpoint file (no SPHCHKPT header)");
  if (bytes.size() < kHeader + kTrailer) throw CheckpointError(what + ": the file is truncated");
  ByteReader head(bytes.data() + 8, kHeader - 8, what);
  const auto version = head.get<std::uint32_t>();
  if (version != kCheckpointVersion)
    throw CheckpointError(what + ": format version " + std::to_string(version) + ", this build reads version " +
                          std::to_string(kCheckpointVersion));
  head.get<std::uint32_t>();
  const auto size = head.get<std::uint64_t>();
  if (bytes.size() < size) throw CheckpointError(what + ": the file is truncated (" + std::to_string(bytes.size()) +
                                                 " of " + std::to_string(size) + " bytes)");
  if (bytes.size() > size || std::memcmp(bytes.data() + size - 8, kEnd, 8) != 0)
    throw CheckpointError(what + ": the file is damaged (no end marker where its size says)");
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + size - kTrailer, 8);
  if (fnv1a64(bytes.data(), size - kTrailer) != stored)
    throw CheckpointError(what + ": the file is damaged (checksum mismatch)");
  ByteReader r(bytes.data() + kHeader, size - kHeader - kTrailer, what);
  Checkpoint c;
  c.config_json = r.get_string();
  c.run_options = r.get_string();
  c.world = r.get_string();
  c.extra = r.get_string();
  if (r.left() != 0) r.fail("the sections do not fill the file");
  return c;
}

std::string write_checkpoint(const std::string& path, const Checkpoint& c) {
  const std::string bytes = encode_checkpoint(c);
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return "cannot write " + tmp + ": " + std::strerror(errno);
  const bool ok = write_all(fd, bytes) && ::fsync(fd) == 0;
  const int err = errno;
  if (::close(fd) != 0 || !ok) {
    ::unlink(tmp.c_str());
    return "cannot write " + tmp + ": " + std::strerror(ok ? errno : err);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    return "cannot rename " + tmp + " to " + path + ": " + why;
  }
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {  // the rename itself reaches the disk
    ::fsync(dfd);
    ::close(dfd);
  }
  return "";
}

Checkpoint read_checkpoint(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw CheckpointError("checkpoint " + path + ": is a directory");
  if (!std::filesystem::exists(path, ec)) throw CheckpointError("checkpoint " + path + ": no such file");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw CheckpointError("checkpoint " + path + ": cannot be opened");
  std::ostringstream s;
  s << f.rdbuf();
  if (f.bad()) throw CheckpointError("checkpoint " + path + ": read error");
  return decode_checkpoint(s.str(), path);
}

}  // namespace sph

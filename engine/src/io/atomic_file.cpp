#include "sph/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>

namespace sph {
namespace {

std::atomic<testing::WriteFn> g_write{nullptr};

/// Writes all of `bytes` to fd (retrying short writes and EINTR); 0, or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
  const testing::WriteFn fn = g_write.load();
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = fn ? fn(fd, bytes.data() + done, bytes.size() - done)
                         : ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

std::string failure(const std::filesystem::path& path, int err) {
  return "cannot write " + path.string() + ": " + std::strerror(err);
}

/// fsyncs the folder holding `path`, so a rename in it survives a crash; errors ignored (some file
/// systems refuse fsync on a folder).
void sync_parent(const std::filesystem::path& path) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

/// True when `path` exists and is not a regular file (a device, a pipe): written in place.
bool is_special(const std::filesystem::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

/// Puts a finished temporary in place: the write's error `err` (0: none), then fsync, close and the rename of
/// `tmp` onto `path`; on any failure the temporary is removed. "" or the message of the first failure.
std::string seal(int fd, int err, const std::filesystem::path& tmp, const std::filesystem::path& path) {
  if (!err && ::fsync(fd) != 0 && errno != EINVAL) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  if (!err && ::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    ::unlink(tmp.c_str());
    return failure(path, err);
  }
  sync_parent(path);
  return {};
}

}  // namespace

std::uint32_t crc32_of(std::string_view bytes, std::uint32_t crc) {
  uLong c = crc;
  std::size_t done = 0;
  while (done < bytes.size()) {  // zlib takes uInt lengths
    const std::size_t n = std::min<std::size_t>(bytes.size() - done, 1u << 30);
    c = ::crc32(c, reinterpret_cast<const Bytef*>(bytes.data() + done), static_cast<uInt>(n));
    done += n;
  }
  return static_cast<std::uint32_t>(c);
}

void remove_stale_temporaries(const std::filesystem::path& dir, std::string_view prefix) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const auto dot = name.rfind(".tmp.");
    if (dot == std::string::npos || dot + 5 >= name.size() || !name.starts_with(prefix)) continue;
    if (name.find_first_not_of("0123456789", dot + 5) != std::string::npos) continue;
    std::filesystem::remove(e.path(), ec);
  }
}

std::string write_file_atomic(const std::filesystem::path& path, std::string_view bytes, FileStamp* stamp) {
  if (stamp) *stamp = {bytes.size(), crc32_of(bytes)};
  if (is_special(path)) {  // /dev/full, /dev/null, a pipe: no temporary beside it
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return failure(path, errno);
    const int err = write_all(fd, bytes);
    ::close(fd);
    return err ? failure(path, err) : std::string();
  }
  const std::filesystem::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return failure(path, errno);
  return seal(fd, write_all(fd, bytes), tmp, path);
}

// ---- GrowingFile -----------------------------------------------------------------------------------

GrowingFile::~GrowingFile() {
  if (fd_ >= 0) {
    (void)flush();
    ::close(fd_);
  }
}

std::string GrowingFile::error(const char* what) const { return "cannot write " + path_.string() + ": " + what; }

std::string GrowingFile::open(const std::filesystem::path& path) {
  path_ = path;
  part_ = path.string() + ".part";
  stamp_ = {};
  buffer_.clear();
  fd_ = ::open(part_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  return fd_ < 0 ? failure(path_, errno) : std::string();
}

std::string GrowingFile::resume(const std::filesystem::path& path, const FileStamp& at) {
  path_ = path;
  part_ = path.string() + ".part";
  buffer_.clear();
  std::error_code ec;
  if (!std::filesystem::exists(part_, ec) && std::filesystem::exists(path_, ec) && ::rename(path_.c_str(), part_.c_str()) != 0)
    return failure(path_, errno);
  const auto size = std::filesystem::file_size(part_, ec);
  if (ec) return error("missing (neither it nor its .part is there)");
  if (size < at.bytes)
    return error(("shorter than at the checkpoint (" + std::to_string(size) + " of " + std::to_string(at.bytes) +
                  " bytes)").c_str());
  std::filesystem::resize_file(part_, at.bytes, ec);
  if (ec) return failure(path_, ec.value());
  fd_ = ::open(part_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) return failure(path_, errno);
  stamp_ = at;
  return {};
}

std::string GrowingFile::append(std::string_view text) {
  if (fd_ < 0) return error("not open");
  buffer_.append(text);
  stamp_.bytes += text.size();
  stamp_.crc32 = crc32_of(text, stamp_.crc32);
  return buffer_.size() >= (1u << 16) ? flush() : std::string();
}

std::string GrowingFile::flush() {
  if (fd_ < 0) return error("not open");
  const int err = write_all(fd_, buffer_);
  buffer_.clear();
  return err ? failure(path_, err) : std::string();
}

std::string GrowingFile::finish() {
  if (fd_ < 0) return error("not open");
  const int err = write_all(fd_, buffer_);
  buffer_.clear();
  const int fd = fd_;
  fd_ = -1;
  return seal(fd, err, part_, path_);
}

void GrowingFile::abandon() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  buffer_.clear();
  if (!part_.empty()) ::unlink(part_.c_str());
}

namespace testing {
void set_write_function(WriteFn fn) { g_write.store(fn); }
}  // namespace testing

}  // namespace sph

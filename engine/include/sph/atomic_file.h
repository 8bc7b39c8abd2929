// Whole files written atomically: the bytes go to NAME.tmp.PID in the same folder, are flushed and
// fsync'd, then renamed over NAME (and the folder fsync'd), so a kill at any moment leaves either the
// old file, the complete new one, or nothing, never a partial NAME. A failure (full disk, vanished or
// read-only folder) removes the temporary and reports one message naming the file.
// Also GrowingFile: a file written row by row during a run (diagnostics.csv) as NAME.part, renamed to
// NAME when the run ends.
#pragma once
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sph {

/// What was written: size [bytes] and CRC-32 (zlib's, as gzip and PNG use) of the content.
struct FileStamp {
  std::uint64_t bytes = 0;
  std::uint32_t crc32 = 0;
};

/// Writes `bytes` as the whole of `path` atomically (see above). An existing path that is not a regular
/// file (/dev/null, /dev/full, a pipe) is written in place. Returns "" on success, else "cannot write
/// PATH: REASON"; *stamp (when given) gets the size and CRC-32 of what was written.
std::string write_file_atomic(const std::filesystem::path& path, std::string_view bytes, FileStamp* stamp = nullptr);

/// Removes the NAME.tmp.PID files a killed writer left in `dir` (whole files it was writing when it
/// stopped), those of names beginning with `prefix` only when one is given. The caller owns the folder.
void remove_stale_temporaries(const std::filesystem::path& dir, std::string_view prefix = {});

/// CRC-32 of `bytes` continuing from `crc` (0 to start).
std::uint32_t crc32_of(std::string_view bytes, std::uint32_t crc = 0);

/// A file that grows during a run: written as PATH.part (rows appended through a buffer), flushed at
/// each flush(), then fsync'd and renamed to PATH by finish(). A kill leaves PATH.part (the run did not
/// end); abandon() removes it. Errors are reported as "cannot write PATH: REASON".
class GrowingFile {
 public:
  GrowingFile() = default;
  GrowingFile(const GrowingFile&) = delete;
  GrowingFile& operator=(const GrowingFile&) = delete;
  ~GrowingFile();  ///< closes without renaming (PATH.part stays, as after a kill)

  /// Creates PATH.part (truncating one left by an earlier run); "" or the error.
  std::string open(const std::filesystem::path& path);
  /// Continues PATH.part (or PATH, a file a stopped run finished, renamed back to PATH.part) from where
  /// it stood at `at` (sph resume): cut back to at.bytes and appended to; "" or the error (shorter than
  /// at.bytes, missing).
  std::string resume(const std::filesystem::path& path, const FileStamp& at);
  /// Appends `text`; "" or the error (a full disk shows at the latest at flush()).
  std::string append(std::string_view text);
  /// Pushes the buffered rows to the system (not to the disk); "" or the error.
  std::string flush();
  /// Flushes, fsyncs, closes and renames PATH.part to PATH; "" or the error (PATH.part is then removed).
  std::string finish();
  /// Closes and removes PATH.part (a run stopped by an I/O error).
  void abandon();
  bool is_open() const { return fd_ >= 0; }
  const std::filesystem::path& path() const { return path_; }
  FileStamp stamp() const { return stamp_; }  ///< size and CRC-32 of what was appended

 private:
  std::string error(const char* what) const;
  std::filesystem::path path_, part_;
  int fd_ = -1;
  std::string buffer_;  // rows not yet handed to write(2)
  FileStamp stamp_;
};

namespace testing {
/// Fault injection for tests: when set, every write(2) of the atomic writers goes through this
/// function instead (same contract: bytes written, or -1 with errno). nullptr restores write(2).
using WriteFn = ssize_t (*)(int fd, const void* data, std::size_t size);
void set_write_function(WriteFn fn);
}  // namespace testing

}  // namespace sph

// manifest.json of an output folder: the files a program has completed there, each with its size and
// CRC-32, rewritten atomically (sph/atomic_file.h) each time a file completes. A file not listed was not
// completed (a run killed while writing leaves NAME.tmp.PID or NAME.part, never a listed partial file).
#pragma once
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "sph/atomic_file.h"

namespace sph {

/// One completed file of a manifest: its name in the folder, size and CRC-32.
struct ManifestEntry {
  std::string name;
  FileStamp stamp;
};

class OutputManifest {
 public:
  /// The manifest of `dir` (dir/manifest.json); nothing is written until the first file completes.
  explicit OutputManifest(std::filesystem::path dir) : dir_(std::move(dir)) {}
  /// Writes dir/name atomically and records it (a file listed already is unlisted while it is replaced,
  /// then listed again in its place); "" or "cannot write PATH: REASON".
  std::string write(const std::string& name, std::string_view bytes);
  /// Records a file completed by other means (a GrowingFile) and rewrites manifest.json; "" or the error.
  std::string add(const std::string& name, const FileStamp& stamp);
  /// The manifest's text: {"files": [{"name", "bytes", "crc32" (8 hex digits)}, ...]} in the order the
  /// files were first completed.
  std::string json() const;
  const std::filesystem::path& dir() const { return dir_; }
  /// The files listed now (for a checkpoint), and the list taken back from one (sph resume): nothing is
  /// written until the next file completes.
  std::vector<ManifestEntry> entries() const;
  void restore(std::vector<ManifestEntry> entries);

 private:
  std::string json_locked() const;
  std::filesystem::path dir_;
  mutable std::mutex mutex_;  // frames are recorded from the PNG writer's thread
  std::vector<ManifestEntry> entries_;
};

}  // namespace sph

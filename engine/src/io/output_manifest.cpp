#include "sph/output_manifest.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace sph {

std::string OutputManifest::write(const std::string& name, std::string_view bytes) {
  std::ptrdiff_t place = -1;  // where a file written again was listed: it goes back there
  {  // a file written again leaves the list first: the manifest never describes a file being replaced
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const ManifestEntry& e) { return e.name == name; });
    if (it != entries_.end()) {
      place = it - entries_.begin();
      entries_.erase(it);
      const std::string err = write_file_atomic(dir_ / "manifest.json", json_locked());
      if (!err.empty()) return err;
    }
  }
  FileStamp stamp;
  const std::string err = write_file_atomic(dir_ / name, bytes, &stamp);
  if (!err.empty()) return err;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto at = place >= 0 && place <= static_cast<std::ptrdiff_t>(entries_.size()) ? entries_.begin() + place
                                                                                      : entries_.end();
  entries_.insert(at, {name, stamp});
  return write_file_atomic(dir_ / "manifest.json", json_locked());
}

std::string OutputManifest::add(const std::string& name, const FileStamp& stamp) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const ManifestEntry& e) { return e.name == name; });
  if (it != entries_.end()) it->stamp = stamp;
  else entries_.push_back({name, stamp});
  return write_file_atomic(dir_ / "manifest.json", json_locked());
}

std::vector<ManifestEntry> OutputManifest::entries() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_;
}

void OutputManifest::restore(std::vector<ManifestEntry> entries) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_ = std::move(entries);
}

std::string OutputManifest::json() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return json_locked();
}

std::string OutputManifest::json_locked() const {
  // one file a line: {"name": ..., "bytes": ..., "crc32": "8 hex digits"}
  std::string out = "{\"about\": \"files completed in this folder, with size in bytes and CRC-32 (zlib); a file not "
                    "listed is incomplete\",\n \"files\": [";
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x", static_cast<unsigned>(entries_[k].stamp.crc32));
    const nlohmann::ordered_json e = {{"name", entries_[k].name}, {"bytes", entries_[k].stamp.bytes}, {"crc32", crc}};
    out += (k ? ",\n  " : "\n  ") + e.dump();
  }
  return out + "\n ]}\n";
}

}  // namespace sph

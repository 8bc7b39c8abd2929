// A file name that does not overwrite an earlier file: STEM.EXT, else STEM_2.EXT, STEM_3.EXT, ...
// (two screenshots at the same step used to overwrite each other).
#pragma once
#include <filesystem>
#include <string>

namespace sph::gui {

inline std::string unique_path(const std::string& stem, const std::string& ext) {
  std::string path = stem + ext;
  std::error_code ec;  // the non-throwing form: an unreadable name ends the search, the write reports it
  for (int k = 2; std::filesystem::exists(path, ec); ++k) path = stem + "_" + std::to_string(k) + ext;
  return path;
}

}  // namespace sph::gui

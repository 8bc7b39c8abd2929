#include "recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sph::gui {

std::string default_config_dir() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return (std::filesystem::path(xdg) / "sph-sandbox").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (std::filesystem::path(home) / ".config" / "sph-sandbox").string();
  return "";
}

RecentFiles::RecentFiles(std::string dir) {
  if (dir.empty()) dir = default_config_dir();
  if (dir.empty()) return;
  file_ = (std::filesystem::path(dir) / "recent.json").string();
  std::ifstream in(file_);
  if (!in) return;
  try {
    const nlohmann::json doc = nlohmann::json::parse(in);
    for (const auto& p : doc.at("recent"))
      if (files_.size() < kMax) files_.push_back(p.get<std::string>());
  } catch (const std::exception&) {
    files_.clear();
    error_ = file_ + ": key 'recent': not a list of paths; the recent-files list starts empty";
  }
}

bool RecentFiles::add(const std::string& path) {
  std::error_code ec;
  const std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
  files_.erase(std::remove(files_.begin(), files_.end(), abs), files_.end());
  files_.insert(files_.begin(), abs);
  if (files_.size() > kMax) files_.resize(kMax);
  if (file_.empty()) return false;
  const std::filesystem::path target(file_);
  std::filesystem::create_directories(target.parent_path(), ec);
  const std::filesystem::path tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << nlohmann::json{{"recent", files_}}.dump(2) << "\n";
    if (!out.flush()) {
      error_ = file_ + ": cannot write";
      return false;
    }
  }
  std::filesystem::rename(tmp, target, ec);
  if (ec) error_ = file_ + ": cannot write (" + ec.message() + ")";
  return !ec;
}

}  // namespace sph::gui

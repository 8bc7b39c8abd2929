// The recent-files list of the scene panel: scene files opened, newest first (at most 10), kept in
// recent.json under $XDG_CONFIG_HOME/sph-sandbox (or ~/.config/sph-sandbox): {"recent": [PATH, ...]}.
#pragma once
#include <string>
#include <vector>

namespace sph::gui {

class RecentFiles {
 public:
  static constexpr std::size_t kMax = 10;
  /// Reads dir/recent.json (dir empty: the default folder). A missing file is an empty list; a malformed
  /// one too, with error() naming the file.
  explicit RecentFiles(std::string dir = "");
  const std::vector<std::string>& files() const { return files_; }
  /// Puts `path` (made absolute) first and writes the file (atomically); false with error() when it cannot.
  bool add(const std::string& path);
  const std::string& error() const { return error_; }
  const std::string& file() const { return file_; }  ///< the JSON file's path

 private:
  std::string file_, error_;
  std::vector<std::string> files_;
};

/// $XDG_CONFIG_HOME/sph-sandbox, else $HOME/.config/sph-sandbox ("" without either).
std::string default_config_dir();

}  // namespace sph::gui

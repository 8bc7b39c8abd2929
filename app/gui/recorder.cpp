#include "recorder.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "png_writer.h"
#include "sph/atomic_file.h"

namespace sph::gui {

bool Recorder::start(const std::string& dir, std::string* err) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    *err = "cannot create directory '" + dir + "'" + (ec ? ": " + ec.message() : std::string());
    return false;
  }
  sph::remove_stale_temporaries(dir, "frame_");
  first_ = 0;  // after the highest frame_NNNNN.png already there
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!name.starts_with("frame_") || !name.ends_with(".png")) continue;
    const std::string digits = name.substr(6, name.size() - 10);  // frame_NNNNN.png: at most 9 digits
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    first_ = std::max(first_, std::stoi(digits) + 1);
  }
  dir_ = dir;
  frames_ = 0;
  active_ = true;
  return true;
}

bool Recorder::write(ParticleView& view, const render::FrameScene& scene, const render::ViewSettings& settings,
                     int width, int height, std::string* err) {
  if (!active_) return true;
  if (!view.render_rgba(scene, settings, width, height, &pixels_, err)) return false;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", first_ + frames_);
  if (!write_png((std::filesystem::path(dir_) / name).string(), width, height, pixels_, err)) return false;
  ++frames_;
  return true;
}

}  // namespace sph::gui

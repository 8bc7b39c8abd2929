#include "recorder.h"

#include <cstdio>
#include <filesystem>

#include "png_writer.h"

namespace sph::gui {

bool Recorder::start(const std::string& dir, std::string* err) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    *err = "cannot create directory '" + dir + "'" + (ec ? ": " + ec.message() : std::string());
    return false;
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
  std::snprintf(name, sizeof name, "frame_%05d.png", frames_);
  if (!write_png((std::filesystem::path(dir_) / name).string(), width, height, pixels_, err)) return false;
  ++frames_;
  return true;
}

}  // namespace sph::gui

// FrameRecorder: the frame flags checked, the view they set, and the numbered frames rendered and handed to
// the PNG thread at their due times. (The video step: frame_video.cpp.)
#include "frame_recorder.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "async_png_writer.h"
#include "colormap.h"
#include "error_out.h"
#include "field_range.h"
#include "profile_axis.h"
#include "sph/snapshot.h"

namespace sph::cli {

FrameRecorder::FrameRecorder(const FrameOptions& options, std::unique_ptr<OffscreenRenderer> renderer)
    : options_(options),
      renderer_(std::move(renderer)),
      manifest_(options.dir),
      writer_(std::make_unique<AsyncPngWriter>(&manifest_)) {
  view_.color_by = options.color_by;
  view_.cmap = options.cmap;
  view_.auto_range = options.auto_range;
  view_.range_min = options.range_min;
  view_.range_max = options.range_max;
  view_.percentile_lo = options.percentile_lo;
  view_.percentile_hi = options.percentile_hi;
  view_.log_scale = options.log_scale;
  view_.auto_log = options.auto_log;
  view_.residuals = options.residuals;
  view_.high_contrast = options.high_contrast;
  view_.show_walls = !options.hide_walls;
  view_.cut_axis = options.cut_axis;
  view_.cut_at = options.cut_at;
  view_.profile_axis = render::parse_profile_axis(options.profile_axis).value_or(-1);
  view_.panels = options.panels;
}

FrameRecorder::~FrameRecorder() {
  std::string err;
  if (!flush(&err)) std::fprintf(stderr, "sph: %s\n", err.c_str());
}

bool FrameRecorder::flush(std::string* err) { return writer_->wait(err); }

std::unique_ptr<FrameRecorder> FrameRecorder::create(const FrameOptions& o, std::string* err, bool* io_failure) {
  auto bad_size = [](int v) { return v <= 0 || v % 2 != 0 || v > 16384; };
  if (bad_size(o.width) || bad_size(o.height)) {
    fail(err, std::string(flag::kSize) + " " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                  ": width and height must be even numbers of pixels in 2..16384 (video encoders need even sizes)");
    return nullptr;
  }
  if (!render::parse_colormap(o.cmap)) {
    fail(err, std::string(flag::kCmap) + ": unknown colour map '" + o.cmap + "' (choose from " +
                  render::colormap_name_list() + ")");
    return nullptr;
  }
  if (!render::parse_profile_axis(o.profile_axis)) {
    fail(err, std::string(flag::kProfileAxis) + ": unknown axis '" + o.profile_axis + "' (choose x, y, r or off)");
    return nullptr;
  }
  if (o.color_by.empty()) {
    fail(err, std::string(flag::kColorBy) + " must name a field");
    return nullptr;
  }
  if (!(o.every > 0.0) || !std::isfinite(o.every)) {
    fail(err, std::string(flag::kEvery) + " must be a positive time interval");
    return nullptr;
  }
  if (!o.auto_range && !(o.range_max > o.range_min && std::isfinite(o.range_min) && std::isfinite(o.range_max))) {
    fail(err, std::string(flag::kRange) + " must be min:max with min < max");
    return nullptr;
  }
  if (!o.video.empty() && !o.video.ends_with(".mp4") && !o.video.ends_with(".webm") && !o.video.ends_with(".gif")) {
    fail(err, std::string(flag::kVideo) + " " + o.video + ": the name must end in .mp4, .webm or .gif");
    return nullptr;
  }
  if (o.fps <= 0) {
    fail(err, std::string(flag::kFps) + " must be positive");
    return nullptr;
  }
  if (o.dir.empty()) {
    fail(err, std::string(flag::kDir) + " needs an output directory");
    return nullptr;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.dir, ec);
  if (ec || !std::filesystem::is_directory(o.dir)) {
    fail(err, std::string(flag::kDir) + ": cannot create directory '" + o.dir + "'" +
                  (ec ? ": " + ec.message() : std::string()));
    if (io_failure) *io_failure = true;
    return nullptr;
  }
  auto renderer = OffscreenRenderer::create(err, o.gl);
  if (!renderer) return nullptr;
  return std::unique_ptr<FrameRecorder>(new FrameRecorder(o, std::move(renderer)));
}

bool FrameRecorder::frame_due(double t) const { return frames_ == 0 || t >= next_t_; }

void FrameRecorder::continue_from(int frames, double first_t, double next_t, std::vector<sph::ManifestEntry> manifest) {
  frames_ = frames;
  first_t_ = first_t;
  next_t_ = next_t;
  manifest_.restore(std::move(manifest));
}

std::string FrameRecorder::frame_path(int index) const {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return (std::filesystem::path(options_.dir) / name).string();
}

bool FrameRecorder::write_frame(const sph::Snapshot& snap, std::string* err) {
  render::FrameScene scene;
  scene.a = &snap;
  return write_frame(scene, err);
}

bool FrameRecorder::write_frame(const render::FrameScene& scene, std::string* err) {
  const sph::Snapshot& snap = *scene.a;
  if (snap.find(view_.color_by) == nullptr) {
    fail(err, std::string(flag::kColorBy) + ": " + render::missing_field_message(snap, view_.color_by));
    return false;
  }
  if (!renderer_->render(scene, view_, options_.width, options_.height, &pixels_, err)) return false;
  if (!writer_->submit(frame_path(frames_), options_.width, options_.height, &pixels_, err)) return false;
  if (frames_ == 0) first_t_ = snap.t;
  // Next due time: the first multiple of `every` (counted from frame 0) after this snapshot's time.
  const double k = std::floor((snap.t - first_t_) / options_.every + 1e-6) + 1.0;
  next_t_ = first_t_ + k * options_.every - 1e-9 * options_.every;
  ++frames_;
  return true;
}

}  // namespace sph::cli

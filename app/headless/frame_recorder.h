// Headless frames: renders snapshots off-screen (OSMesa or EGL) and writes numbered PNG files, optionally
// joined into a video (or an animated GIF) by ffmpeg afterwards, with a still of the last frame.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "frame_scene.h"
#include "offscreen_renderer.h"  // OffscreenRenderer, render_snapshot_rgba
#include "png_file.h"            // encode_png, write_png
#include "sph/output_manifest.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::cli {

/// Command-line flag names used in FrameRecorder::create's error messages.
namespace flag {
inline constexpr const char* kDir = "--frames";
inline constexpr const char* kEvery = "--every";
inline constexpr const char* kSize = "--size";  // WIDTHxHEIGHT
inline constexpr const char* kColorBy = "--color-by";
inline constexpr const char* kCmap = "--cmap";
inline constexpr const char* kRange = "--range";
inline constexpr const char* kProfileAxis = "--profile-axis";
inline constexpr const char* kVideo = "--video";
inline constexpr const char* kFps = "--fps";
inline constexpr const char* kPanels = "--panels";
}  // namespace flag

struct FrameOptions {
  std::string dir;            ///< output directory (created if missing)
  double every = 0.1;         ///< simulated time between frames (used by frame_due) [time units]
  int width = 1280;           ///< frame width [px], even (video encoders need even sizes)
  int height = 720;           ///< frame height [px], even
  std::string color_by = "rho";
  std::string cmap = "viridis";
  bool auto_range = true;     ///< per-frame min/max of the field; else [range_min, range_max]
  float range_min = 0, range_max = 1;
  float percentile_lo = 0, percentile_hi = 100;  ///< auto range between these percentiles (--range pLO:HI)
  bool log_scale = false;     ///< colour by log10 of the field (--log)
  bool auto_log = true;       ///< log10 when a field spans more than two decades (off: --linear)
  bool residuals = false;     ///< profiles: the strip of the error against the exact curve (--residuals)
  bool high_contrast = false; ///< white-on-black chrome (--high-contrast)
  bool hide_walls = false;    ///< no wall particles in 2D and 3D frames (--hide-walls)
  int cut_axis = -1;          ///< 3D cutaway (--cut): only particles with coordinate cut_axis <= cut_at
  float cut_at = 0.f;
  std::string profile_axis = "off";  ///< 2D: "x" or "y" (profile of the field against it), or "off"
  std::vector<std::string> panels;   ///< profiles: one panel per field (ViewSettings::panels)
  std::string video;          ///< .mp4 (H.264), .webm or .gif (animated, for slides) to make, or empty
  int fps = 30;               ///< video frame rate [frames per second]
  GlBackend gl = GlBackend::Auto;  ///< off-screen context (--gl)
};

class AsyncPngWriter;

class FrameRecorder {
 public:
  /// Flushes; a write error not collected by flush() or make_video() is printed to stderr.
  ~FrameRecorder();
  /// Validates the options (even width/height, known colour map and profile axis, positive interval
  /// and fps) and creates the directory and the context; nullptr with *err naming the offending flag
  /// otherwise (*io_failure set when it is the folder that cannot be made).
  static std::unique_ptr<FrameRecorder> create(const FrameOptions& options, std::string* err, bool* io_failure = nullptr);

  /// True when the snapshot at time t should become the next frame: the first call, then once t
  /// reaches each further multiple of `every` after the first frame's time.
  bool frame_due(double t) const;
  /// Renders dir/frame_00000.png, frame_00001.png, ... The PNG is compressed and written on a
  /// background thread while the caller goes on (a write error shows up at the next call or at
  /// flush). Fails (with the field named and the available ones listed) if the colour-by field is
  /// not in the snapshot.
  bool write_frame(const sph::Snapshot& snap, std::string* err);
  /// The same for a FrameScene (the two runs of a comparison, highlights).
  bool write_frame(const render::FrameScene& scene, std::string* err);
  /// Waits until every frame is on disk; false with the first write error.
  bool flush(std::string* err);
  int frames_written() const { return frames_; }
  std::string frame_path(int index) const;
  /// The time of frame 0 and the time from which the next frame is due (for a checkpoint).
  double first_time() const { return first_t_; }
  double next_due() const { return next_t_; }
  /// The frame folder's manifest (its entries: every frame completed, once flush() returned).
  const sph::OutputManifest& manifest() const { return manifest_; }
  /// Continues a sequence a checkpoint saved: `frames` frames on disk, frame 0 at first_t, the next
  /// due from next_t, the folder's manifest as it listed them. The next frame gets number `frames`.
  void continue_from(int frames, double first_t, double next_t, std::vector<sph::ManifestEntry> manifest);
  /// Removes the VIDEO.tmp.PID.EXT a run killed while ffmpeg ran left beside the video.
  void remove_stale_video() const;

  /// The ffmpeg command line that turns the frames into options.video (a GIF gets its own palette).
  /// `output` (default: options.video) replaces the file it writes.
  std::string ffmpeg_command(const std::string& output = "") const;
  /// Flushes, then runs ffmpeg_command() if options.video is set (true and nothing done otherwise),
  /// and copies the last frame beside the video as its still (still_path()).
  bool make_video(std::string* err);
  /// VIDEO without its extension + "_last.png": the last frame, for a poster or a slide.
  std::string still_path() const;

  const FrameOptions& options() const { return options_; }
  render::ViewSettings& view() { return view_; }  ///< cameras, point sizes: adjustable before frames

 private:
  FrameRecorder(const FrameOptions& options, std::unique_ptr<OffscreenRenderer> renderer);

  FrameOptions options_;
  render::ViewSettings view_;
  std::unique_ptr<OffscreenRenderer> renderer_;
  sph::OutputManifest manifest_;  // the frame folder's manifest.json (written from the PNG thread)
  std::unique_ptr<AsyncPngWriter> writer_;
  std::vector<std::uint8_t> pixels_;
  int frames_ = 0;
  double first_t_ = 0.0;  // time of frame 0
  double next_t_ = 0.0;   // time from which the next frame is due
};

}  // namespace sph::cli

// Off-screen rendering, PNG files (stb_image_write + zlib) written on a background thread, and the
// frame sequence with its ffmpeg step. (Sections below; split into files if this grows.)
#include "frame_recorder.h"

#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <thread>

#include "colormap.h"
#include "field_range.h"
#include "profile_axis.h"
#include "sph/snapshot.h"

// stb_image_write's own deflate is ~4x slower than zlib at its fastest level, which compresses these
// frames (flat backgrounds) about as well: hand stb zlib's compress2. The buffer must come from malloc
// (stb frees it with STBIW_FREE).
static unsigned char* sph_png_deflate(unsigned char* data, int length, int* out_length, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (out == nullptr || compress2(out, &size, data, static_cast<uLong>(length), Z_BEST_SPEED) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(size);
  return out;
}

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // private copy: no clash with another user of stb in the same binary
#define STBIW_ZLIB_COMPRESS sph_png_deflate
#include <stb/stb_image_write.h>

namespace sph::cli {

namespace {

void fail(std::string* err, const std::string& msg) {
  if (err) *err = msg;
}

// Single-quoted for /bin/sh: ' becomes '\''.
std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool on_path(const char* program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

}  // namespace

// ---- OffscreenRenderer ---------------------------------------------------------------------------

std::unique_ptr<OffscreenRenderer> OffscreenRenderer::create(std::string* err, GlBackend backend) {
  auto r = std::unique_ptr<OffscreenRenderer>(new OffscreenRenderer());
  r->context_ = create_offscreen_context(backend, err);
  if (!r->context_) return nullptr;
  // A small target first: the renderer needs a current context to compile its shaders.
  if (!r->context_->make_current(16, 16, err)) return nullptr;
  if (!r->renderer_.init(r->context_->proc_loader(), err)) return nullptr;
  return r;
}

OffscreenRenderer::~OffscreenRenderer() {
  // Another context may be current on this thread: the renderer's GL objects live in this one.
  std::string ignored;
  if (context_ && context_->width() > 0 && context_->make_current(context_->width(), context_->height(), &ignored))
    renderer_.shutdown();
}

bool OffscreenRenderer::render(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
                               std::vector<std::uint8_t>* rgba, std::string* err) {
  render::FrameScene scene;
  scene.a = &snap;
  return render(scene, view, width, height, rgba, err);
}

bool OffscreenRenderer::render(const render::FrameScene& scene, const render::ViewSettings& view, int width,
                               int height, std::vector<std::uint8_t>* rgba, std::string* err) {
  if (!context_->make_current(width, height, err)) return false;
  renderer_.render(scene, view, width, height);
  last_gl_error_ = renderer_.gl().GetError();
  return context_->read_pixels(rgba, err);
}

bool render_snapshot_rgba(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
                          std::vector<std::uint8_t>* rgba, std::string* err) {
  auto r = OffscreenRenderer::create(err);
  return r && r->render(snap, view, width, height, rgba, err);
}

std::string encode_png(int width, int height, const std::vector<std::uint8_t>& rgba) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (width <= 0 || height <= 0 || rgba.size() < n * 4) return {};
  // The "up" filter for every row: as small as stb's per-row search on these frames, at half the time.
  static std::once_flag tuned;
  std::call_once(tuned, [] { stbi_write_force_png_filter = 2; });
  std::vector<std::uint8_t> rgb(n * 3);  // frames are opaque: drop alpha (smaller, faster files)
  for (std::size_t i = 0; i < n; ++i) {
    rgb[3 * i] = rgba[4 * i];
    rgb[3 * i + 1] = rgba[4 * i + 1];
    rgb[3 * i + 2] = rgba[4 * i + 2];
  }
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3)) return {};
  return png;
}

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba,
               std::string* err, sph::OutputManifest* manifest) {
  const std::string png = encode_png(width, height, rgba);
  if (png.empty()) {
    fail(err, "cannot write " + path + ": the image cannot be encoded");
    return false;
  }
  const std::string e = manifest ? manifest->write(std::filesystem::path(path).filename().string(), png)
                                 : sph::write_file_atomic(path, png);
  if (!e.empty()) {
    fail(err, e);
    return false;
  }
  return true;
}

// ---- AsyncPngWriter ------------------------------------------------------------------------------

/// One background thread that writes one PNG at a time: the next frame is rendered while the
/// previous one is compressed. submit() waits for the previous write (so at most two frames are in
/// memory) and hands over the pixels.
class AsyncPngWriter {
 public:
  explicit AsyncPngWriter(sph::OutputManifest* manifest) : manifest_(manifest), thread_([this] { run(); }) {}
  ~AsyncPngWriter() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }

  /// Queues rgba for `path` (swapping buffers with the caller); false with the previous write's error.
  bool submit(const std::string& path, int width, int height, std::vector<std::uint8_t>* rgba, std::string* err) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return !busy_; });
    if (!error_.empty()) return take_error(err);
    path_ = path;
    width_ = width;
    height_ = height;
    pixels_.swap(*rgba);
    busy_ = true;
    wake_.notify_all();
    return true;
  }

  /// Waits for the write in flight; false with its error.
  bool wait(std::string* err) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return !busy_; });
    return error_.empty() || take_error(err);
  }

 private:
  bool take_error(std::string* err) {
    fail(err, error_);
    error_.clear();
    return false;
  }

  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return busy_ || quit_; });
      if (!busy_ && quit_) return;
      lock.unlock();
      std::string err;
      const bool ok = write_png(path_, width_, height_, pixels_, &err, manifest_);  // the job is ours while busy_
      lock.lock();
      if (!ok) error_ = err;
      busy_ = false;
      done_.notify_all();
    }
  }

  sph::OutputManifest* manifest_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  bool busy_ = false, quit_ = false;
  std::string path_, error_;
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> pixels_;
  std::thread thread_;  // last: starts after the members it uses exist
};

// ---- FrameRecorder -------------------------------------------------------------------------------

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

std::string FrameRecorder::ffmpeg_command(const std::string& output) const {
  const std::string pattern = (std::filesystem::path(options_.dir) / "frame_%05d.png").string();
  const std::string out =
      shell_quote(!output.empty() ? output : options_.video.empty() ? std::string("video.mp4") : options_.video);
  const std::string in = "ffmpeg -y -loglevel error -framerate " + std::to_string(options_.fps) + " -i " +
                         shell_quote(pattern);
  if (options_.video.ends_with(".gif"))  // one palette made for these frames: flat colours stay flat
    return in + " -filter_complex \"[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none\" " +
           out;
  if (options_.video.ends_with(".webm")) return in + " -c:v libvpx-vp9 -pix_fmt yuv420p -b:v 0 -crf 30 " + out;
  // yuv420p: playable everywhere (needs even sizes, checked in create); crf 18: visually lossless.
  return in + " -c:v libx264 -pix_fmt yuv420p -crf 18 -movflags +faststart " + out;
}

std::string FrameRecorder::still_path() const {
  std::filesystem::path p(options_.video.empty() ? std::string("video.mp4") : options_.video);
  return (p.parent_path() / (p.stem().string() + "_last.png")).string();
}

bool FrameRecorder::make_video(std::string* err) {
  if (!flush(err)) return false;
  if (options_.video.empty()) return true;
  if (frames_ == 0) {
    fail(err, std::string(flag::kVideo) + ": no frames were written, so there is no video to make");
    return false;
  }
  if (!on_path("ffmpeg")) {
    fail(err, std::string(flag::kVideo) + ": ffmpeg is not installed (apt-get install ffmpeg); the frames are in '" +
                  options_.dir + "', make the video later with:\n  " + ffmpeg_command());
    return false;
  }
  // ffmpeg writes VIDEO.tmp.PID.EXT (it picks the format from the extension), renamed when complete
  const std::filesystem::path video(options_.video);
  const std::filesystem::path tmp =
      video.parent_path() / (video.stem().string() + ".tmp." + std::to_string(::getpid()) + video.extension().string());
  const int status = std::system(ffmpeg_command(tmp.string()).c_str());
  std::error_code ec;
  if (status != 0) {
    std::filesystem::remove(tmp, ec);
    fail(err, std::string(flag::kVideo) + ": ffmpeg failed (status " + std::to_string(status) + "): " +
                  ffmpeg_command());
    return false;
  }
  std::filesystem::rename(tmp, video, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    fail(err, std::string(flag::kVideo) + ": cannot write " + options_.video + ": " + ec.message());
    return false;
  }
  std::ifstream last(frame_path(frames_ - 1), std::ios::binary);  // the still: the last frame, atomically
  const std::string png((std::istreambuf_iterator<char>(last)), std::istreambuf_iterator<char>());
  const std::string e = last ? sph::write_file_atomic(still_path(), png) : "cannot read " + frame_path(frames_ - 1);
  if (!e.empty()) {
    fail(err, std::string(flag::kVideo) + ": " + e);
    return false;
  }
  return true;
}

}  // namespace sph::cli

// The video step of a frame sequence: the ffmpeg command line, ffmpeg run into a temporary file renamed when
// complete, and the still of the last frame beside the video.
#include "frame_recorder.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "error_out.h"
#include "sph/atomic_file.h"

namespace sph::cli {

namespace {

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

/// Runs `command` with /bin/sh as std::system does (the wait status, -1 if it cannot start), but as a
/// process that dies with this thread: a run killed with kill -9 while ffmpeg works leaves no ffmpeg
/// writing on beside a resumed run. `exec` keeps the death signal from the shell to ffmpeg.
int run_dying_with_us(const std::string& command) {
  const std::string line = "exec " + command;
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {  // the child: async-signal-safe calls only
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent) ::_exit(127);
    ::execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

}  // namespace

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

void FrameRecorder::remove_stale_video() const {
  if (options_.video.empty()) return;
  const std::filesystem::path video(options_.video);  // VIDEO.tmp.PID.EXT, as make_video names it
  const std::string head = video.stem().string() + ".tmp.", tail = video.extension().string();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(video.parent_path().empty() ? "." : video.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() <= head.size() + tail.size() || !name.starts_with(head) || !name.ends_with(tail)) continue;
    const std::string pid = name.substr(head.size(), name.size() - head.size() - tail.size());
    if (pid.find_first_not_of("0123456789") == std::string::npos) std::filesystem::remove(e.path(), ec);
  }
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
  const int status = run_dying_with_us(ffmpeg_command(tmp.string()));
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

// Checkpoints of `sph run --out DIR`: DIR/checkpoint.sph (sph/checkpoint.h) with the run's options and
// where its output files and frames stood, written every --checkpoint-every of simulated time and when a
// signal stops the run; `sph resume DIR` (cli_resume.cpp) continues from it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "cli_run.h"
#include "run_output.h"
#include "sph/checkpoint.h"
#include "sph/world.h"

namespace sph::cli {

/// Where a frame sequence (--frames, --video) stood at a checkpoint: every frame so far on disk, when the
/// next ones fall due, and the frame folder's manifest. The video is made from the frames at the end.
struct FrameResume {
  bool active = false;
  int next_frame = 1;                   ///< the run loop's next frame is due at next_frame * --every
  int written = 0;                      ///< frame_00000.png ... frame_{written - 1}.png are complete
  double first_t = 0.0, next_t = 0.0;   ///< the time of frame 0 and the recorder's next due time
  std::vector<ManifestEntry> manifest;  ///< the frame folder's manifest.json entries
};

/// A checkpoint read back and checked, with the caller's part decoded.
struct ResumePoint {
  std::string path;                  ///< DIR/checkpoint.sph
  Checkpoint ck;
  OutputResume output;
  int next_out = 1;                  ///< the run loop's next particle output
  std::int64_t next_checkpoint = 1;  ///< the next checkpoint is at next_checkpoint * checkpoint_every
  double t_end = 0.0;                ///< the end time of the run that wrote it (sph resume --until may change it)
  FrameResume frames;                ///< the frame sequence (inactive without --frames)
};

/// DIR/checkpoint.sph.
std::string checkpoint_path(const std::string& dir);
/// The options that matter to a run's results and files, as JSON text, and back (throws CheckpointError
/// naming `path`).
std::string options_json(const RunOptions& opt);
RunOptions options_from_json(const std::string& text, const std::string& path);
/// Reads and checks DIR/checkpoint.sph and the output files it continues; fills `opt` with the run's
/// options (--out DIR). Throws CheckpointError naming the file; nothing is changed on disk.
ResumePoint load_resume_point(const std::string& dir, RunOptions* opt);
/// Why `opt` cannot take checkpoints ("" if it can): they need --out, and do not cover --compare.
std::string checkpoint_unsupported(const RunOptions& opt);
/// The run stopped on signal `sig` after a step: prints where and how to continue; returns 130 or 143.
int report_stop(int sig, const World& world, const RunOptions& opt, bool checkpointed);

/// Writes the checkpoints of one run.
class Checkpointer {
 public:
  Checkpointer(const RunOptions& opt, const RunConfig& cfg, const ResumePoint* resume);
  ~Checkpointer();
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;
  /// A periodic checkpoint is due at time t (the run passed the next multiple of --checkpoint-every).
  bool due(double t) const;
  /// Writes DIR/checkpoint.sph whole (temp name, fsync, rename), with the frame sequence's state (every
  /// frame it counts already on disk); throws IoError.
  void write(const World& world, RunOutput& out, int next_out, const FrameResume& frames);
  const std::string& path() const { return path_; }

 private:
  std::string path_, tmp_, options_, config_;
  double every_ = 0.0;
  std::int64_t next_ = 1;
};

}  // namespace sph::cli

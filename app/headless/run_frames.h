// The frames of `sph run --frames` (the headless-render build): the frame flags checked against the scene's
// fields and the recorder opened before anything is written, each frame (run B's beside run A's in a
// comparison) written when due, and the video made at the end.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "cli_compare.h"
#include "cli_sweep.h"
#include "cli_run.h"
#include "frame_recorder.h"
#include "run_checkpoint.h"
#include "sph/snapshot.h"
#include "sph/trail_log.h"

namespace sph::cli {

class RunFrames {
 public:
  /// Checks the frame flags against world's fields and opens the recorder (none without --frames):
  /// ConfigError names a bad flag, IoError a frame folder that cannot be made. With `resume` (an active
  /// FrameResume of sph resume) the sequence goes on after the frames it counts.
  RunFrames(const RunOptions& opt, const RunConfig& cfg, const World& world, const FrameResume* resume = nullptr);

  bool active() const { return rec_ != nullptr; }
  /// The simulated time at which the next frame is due.
  double next_time() const { return next_frame_ * opt_.every; }
  /// Counts the next frame as passed (the world stepped beyond its time).
  void advance() { ++next_frame_; }
  /// Where the sequence stands, for a checkpoint: waits until every frame so far is on disk (IoError when
  /// one cannot be written). Inactive without --frames.
  FrameResume resume_state();
  /// Samples the orbit trails of a few-body scene (after every step: sph/trail_log.h).
  void record_trails(const World& world) { trails_.record(world); }
  /// Writes the frame of world now (with run B, compared, or a sweep's runs); IoError when it cannot be written.
  void write(const World& world, const World* b, const std::optional<CompareSetup>& compare,
             const SweepRuns* sweep = nullptr);
  /// Waits for the PNG files, prints where they are and makes the video (--video): kOk, or kIoError
  /// when the video cannot be made; IoError when a frame cannot be written.
  int finish();

 private:
  const RunOptions& opt_;
  std::unique_ptr<FrameRecorder> rec_;
  int next_frame_ = 1;
  std::string err_;
  Snapshot snap_, snap_b_;  // what the last frame showed
  std::vector<Snapshot> snap_sweep_;
  TrailLog trails_;         // run A's orbit trails (a resumed run's start again at the resume)
};

}  // namespace sph::cli

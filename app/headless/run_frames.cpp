// RunFrames: the frame flags of `sph run` turned into a FrameRecorder (refused with the flag named), the
// snapshots of a frame with the probed particle's tree walk, and the end of the sequence.
#include "run_frames.h"

#include <cstdio>

#include "cli_common.h"
#include "sph/compare.h"
#include "exit_codes.h"
#include "frame_size.h"
#include "profile_axis.h"
#include "profile_view.h"
#include "run_output.h"
#include "sph/memory_budget.h"
#include "sph/suggest.h"
#include "sph/world.h"
#include "value_parsers.h"

namespace sph::cli {
namespace {

/// --range into fo: auto, pLO:HI (percentiles) or MIN:MAX; ConfigError when malformed.
void set_range(const std::string& range, FrameOptions& fo) {
  if (!range.empty() && range[0] == 'p') {  // pLO:HI, automatic between percentiles (the GUI's p1:99)
    float lo = 0, hi = 0;
    if (!parse_range(range.substr(1), &lo, &hi) || !(lo >= 0.f) || !(hi <= 100.f) || !(hi > lo))
      throw ConfigError("--range " + range + ": expected pLO:HI with 0 <= LO < HI <= 100");
    fo.percentile_lo = lo;
    fo.percentile_hi = hi;
  } else if (range != "auto") {
    float lo = 0, hi = 0;
    if (!parse_range(range, &lo, &hi) || !(hi > lo))
      throw ConfigError("--range " + range + ": expected auto, pLO:HI (percentiles) or MIN:MAX with MIN < MAX");
    fo.auto_range = false;
    fo.range_min = lo;
    fo.range_max = hi;
  }
}

std::unique_ptr<FrameRecorder> make_recorder(const RunOptions& opt) {
  if (opt.frames.empty()) return nullptr;
  FrameOptions fo;
  fo.dir = opt.frames;
  fo.fps = opt.fps;
  fo.gl = gl_backend_from_environment();
  if (!opt.gl.empty() && !parse_gl_backend(opt.gl, &fo.gl))
    throw ConfigError("--gl " + opt.gl + ": expected osmesa, egl or auto" + did_you_mean(opt.gl, {"osmesa", "egl", "auto"}) +
                      " (this build has: " + built_gl_backends() + ")");
  fo.every = opt.every;
  if (!(opt.every > 0.0)) throw ConfigError("--every must be > 0");
  int w = 0, h = 0;
  if (!render::parse_frame_size(opt.size, &w, &h))
    throw ConfigError("--size " + opt.size + ": expected WIDTHxHEIGHT, e.g. 1280x720");
  fo.width = w;
  fo.height = h;
  fo.color_by = opt.color_by;
  fo.cmap = opt.cmap;
  set_range(opt.range, fo);
  fo.log_scale = opt.log_scale;
  fo.auto_log = !opt.linear;
  fo.residuals = opt.residuals;
  fo.high_contrast = opt.high_contrast;
  fo.hide_walls = opt.hide_walls;
  if (!opt.cut.empty() && !parse_cut(opt.cut, &fo.cut_axis, &fo.cut_at))
    throw ConfigError("--cut " + opt.cut + ": expected AXIS=VALUE with AXIS x, y or z, e.g. z=0");
  fo.profile_axis = opt.profile_axis;
  fo.panels = split_names(opt.panels);
  fo.video = opt.video;
  std::string err;
  const double need = frame_memory_bytes(w, h), avail = available_memory_bytes();
  if (need > avail)
    throw ConfigError("--size " + opt.size + ": a frame needs about " + memory_text(need) + " of memory, more than the " +
                      memory_text(avail) + " available (MemAvailable, ulimit -v)");
  bool io_failure = false;
  auto rec = FrameRecorder::create(fo, &err, &io_failure);
  if (!rec && io_failure) throw IoError(err);  // the folder cannot be made: exit 4
  if (!rec) throw ConfigError(err);
  return rec;
}

/// Refuses an unknown colour-by field, panel field or tree probe before anything is written; returns the
/// colour-by field (the default: rho where the scene has it, else its first field).
std::string check_fields(const RunOptions& opt, const RunConfig& cfg, const Snapshot& snap) {
  std::string color_by = opt.color_by;
  if (color_by.empty()) color_by = snap.find("rho") || snap.fields.empty() ? "rho" : snap.fields.front().name;
  if (opt.tree_probe >= 0 && cfg.params.physics.gravity != GravityType::Tree)
    throw ConfigError("--tree-probe: scene " + cfg.scene->name + " has no Barnes-Hut tree (physics.gravity = " +
                      cfg.params.physics.get(Slot::Gravity) + ")");
  if (opt.tree_probe >= 0 && static_cast<std::size_t>(opt.tree_probe) >= snap.count)
    throw ConfigError("--tree-probe " + std::to_string(opt.tree_probe) + ": scene " + cfg.scene->name + " has " +
                      std::to_string(snap.count) + " particles");
  std::string known;
  std::vector<std::string> names;
  for (const auto& f : snap.fields) {
    known += " " + f.name;
    names.push_back(f.name);
  }
  if (!snap.find(color_by))
    throw ConfigError("--color-by " + color_by + ": no such field in scene " + cfg.scene->name +
                      did_you_mean(color_by, names) + " (fields:" + known + ")");
  for (const std::string& p : render::panel_fields(snap, split_names(opt.panels)))
    if (!snap.find(p))
      throw ConfigError(std::string(flag::kPanels) + " " + opt.panels + ": no field '" + p + "' in scene " +
                        cfg.scene->name + did_you_mean(p, names) + " (fields:" + known + "; v is vx in 1D, else speed)");
  return color_by;
}

}  // namespace

RunFrames::RunFrames(const RunOptions& opt, const RunConfig& cfg, const World& world, const FrameResume* resume)
    : opt_(opt) {
  RunOptions fopt = opt;  // with the colour-by field resolved
  if (!opt.frames.empty()) fopt.color_by = check_fields(opt, cfg, world.report().snapshot());
  rec_ = make_recorder(fopt);  // validates the frame flags before anything is written
  if (rec_) {  // this run owns the frame folder: what a killed run was writing there goes
    remove_stale_temporaries(opt.frames);  // frame_NNNNN.png.tmp.PID, manifest.json.tmp.PID
    rec_->remove_stale_video();
  }
  if (rec_ && resume && resume->active) {
    rec_->continue_from(resume->written, resume->first_t, resume->next_t, resume->manifest);
    next_frame_ = resume->next_frame;
  }
  if (rec_ && rec_->view().profile_axis >= 0 && !render::draws_profile(cfg.scene->dim, rec_->view().profile_axis))
    std::fprintf(stderr, "sph: note: %s applies to 2D scenes; %s is %dD, so it is ignored\n", flag::kProfileAxis,
                 cfg.scene->name.c_str(), cfg.scene->dim);
  if (rec_ && !opt.cut.empty() && cfg.scene->dim != 3)
    std::fprintf(stderr, "sph: note: --cut applies to 3D scenes; ignored\n");
  if (rec_ && !opt.panels.empty() && !render::draws_profile(cfg.scene->dim, rec_->view().profile_axis))
    std::fprintf(stderr, "sph: note: %s applies to profiles (1D scenes, or %s x|y|r); ignored\n", flag::kPanels,
                 flag::kProfileAxis);
}

void RunFrames::write(const World& world, const World* b, const std::optional<CompareSetup>& compare,
                      const SweepRuns* sweep) {
  snap_ = world.report().snapshot();  // with the probed particle's tree walk when asked for
  trails_.record(world);  // the first frame's start (a no-op when the step already recorded this time)
  trails_.decorate(snap_);
  if (opt_.tree_probe >= 0) {
    snap_.tree_cells = world.report().tree_cells(static_cast<std::size_t>(opt_.tree_probe));
    snap_.tree_probe = opt_.tree_probe;
  }
  render::FrameScene scene;
  scene.a = &snap_;
  if (b) {
    snap_b_ = b->report().snapshot();
    scene.b = &snap_b_;
    scene.label_a = compare->label_a;
    scene.label_b = compare->label_b;
    scene.errors_a = reference_errors(world);
    scene.errors_b = reference_errors(*b);
  }
  if (sweep) {  // run A labelled with its own value of the key, each run with its value
    scene.sweep_key = sweep->key();
    render::name_sweep_run_a(scene, compare_label(world.config(), {sweep->key() + "=0"}));
    scene.errors_a = reference_errors(world);
    snap_sweep_.resize(sweep->size());
    for (std::size_t k = 0; k < sweep->size(); ++k) {
      snap_sweep_[k] = sweep->world(k).report().snapshot();
      render::add_sweep_run(scene, &snap_sweep_[k], sweep->label(k), reference_errors(sweep->world(k)));
    }
  }
  if (!rec_->write_frame(scene, &err_)) throw IoError(err_);
}

FrameResume RunFrames::resume_state() {
  FrameResume r;
  if (!rec_) return r;
  if (!rec_->flush(&err_)) throw IoError(err_);  // the checkpoint counts only frames on disk
  r.active = true;
  r.next_frame = next_frame_;
  r.written = rec_->frames_written();
  r.first_t = rec_->first_time();
  r.next_t = rec_->next_due();
  r.manifest = rec_->manifest().entries();
  return r;
}

int RunFrames::finish() {
  if (!rec_) return kOk;
  if (!rec_->flush(&err_)) throw IoError(err_);  // PNGs are compressed in the background
  std::printf("%d frames in %s; make a video with:\n  %s\n", rec_->frames_written(), opt_.frames.c_str(),
              rec_->ffmpeg_command().c_str());
  if (opt_.video.empty()) return kOk;
  if (!rec_->make_video(&err_)) {
    std::fprintf(stderr, "sph: %s\n", err_.c_str());
    return kIoError;
  }
  std::printf("video %s (%d frames at %d/s), last frame %s\n", opt_.video.c_str(), rec_->frames_written(), opt_.fps,
              rec_->still_path().c_str());
  return kOk;
}

}  // namespace sph::cli

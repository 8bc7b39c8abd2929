#include "cli_run.h"
#include "sph/thread_wait.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_common.h"
#include "exit_codes.h"
#include "run_checkpoint.h"
#include "run_output.h"
#include "run_signals.h"
#include "sph/config.h"
#include "sph/ic_export.h"
#include "sph/memory_budget.h"
#include "sph/suggest.h"
#include "sph/world.h"
#ifdef SPH_HAVE_FRAMES
#include "frame_recorder.h"
#include "frame_size.h"
#include "profile_view.h"
#include "profile_axis.h"
#include "progress.h"
#include "value_parsers.h"
#endif

namespace sph::cli {
namespace {

sph::RunConfig resolve(const RunOptions& opt) {
  sph::RunConfig cfg = sph::RunConfig::load(opt.scene);
  apply_sets(cfg, opt.sets);
  if (opt.until >= 0.0) cfg.params.time.t_end = opt.until;
  cfg.validate();
  check_run_memory(cfg);  // an enormous particle count is refused before anything is allocated
  return cfg;
}

#ifdef SPH_HAVE_FRAMES
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
  if (!opt.range.empty() && opt.range[0] == 'p') {  // pLO:HI, automatic between percentiles (the GUI's p1:99)
    float lo = 0, hi = 0;
    if (!parse_range(opt.range.substr(1), &lo, &hi) || !(lo >= 0.f) || !(hi <= 100.f) || !(hi > lo))
      throw ConfigError("--range " + opt.range + ": expected pLO:HI with 0 <= LO < HI <= 100");
    fo.percentile_lo = lo;
    fo.percentile_hi = hi;
  } else if (opt.range != "auto") {
    float lo = 0, hi = 0;
    if (!parse_range(opt.range, &lo, &hi) || !(hi > lo))
      throw ConfigError("--range " + opt.range + ": expected auto, pLO:HI (percentiles) or MIN:MAX with MIN < MAX");
    fo.auto_range = false;
    fo.range_min = lo;
    fo.range_max = hi;
  }
  fo.log_scale = opt.log_scale;
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
#endif

/// Run B to run A's time; a divergence of B names it.
void advance_b(World& b, double t, const CompareSetup& setup) {
  try {
    b.advance_to(t);
  } catch (const DivergedError&) {
    std::fprintf(stderr, "sph: run %s diverged:\n", setup.label_b.c_str());
    throw;
  }
}

/// The run's "warnings" section on stderr: what it tolerated (nothing is printed for a clean run).
void print_warnings(const World& world) {
  if (world.checks().warnings().empty()) return;
  std::fprintf(stderr, "warnings (%zu):\n", world.checks().warnings().size());
  for (const RunWarning& w : world.checks().warnings())
    std::fprintf(stderr, "  [%s] from step %lld (t = %g, %lld checks): %s\n", w.kind.c_str(),
                 static_cast<long long>(w.step), w.t, static_cast<long long>(w.times), w.message.c_str());
}

}  // namespace

int list_command() {
  for (const auto& s : scene_registry()) std::printf("%-24s %dD  %s\n", s.name.c_str(), s.dim, s.description.c_str());
  return kOk;
}

int check_command(const RunOptions& opt) {
  try {
    const sph::RunConfig cfg = resolve(opt);
    std::printf("%s: valid (scene %s)\n", opt.scene.c_str(), cfg.scene->name.c_str());
    return kOk;
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: invalid scene: %s\n", e.what());
    return kInvalidScene;
  }
}

int run_command(const RunOptions& opt, const ResumePoint* resume) {
  sph::RunConfig cfg;
  try {
    cfg = resolve(opt);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: invalid scene: %s\n", e.what());
    return kInvalidScene;
  }
  RunConfig as_saved = cfg;  // sph resume --until may move the end: the rest must be as it was
  if (resume) as_saved.params.time.t_end = resume->t_end;
  if (resume && as_saved.to_json() != resume->ck.config_json) {
    std::fprintf(stderr, "sph: checkpoint %s: scene %s resolves to other parameters now than when the run "
                 "started (its file or this build changed); it cannot be continued\n",
                 resume->path.c_str(), opt.scene.c_str());
    return kInvalidScene;
  }
  if (opt.checkpoint_every > 0.0 && !checkpoint_unsupported(opt).empty()) {
    std::fprintf(stderr, "sph: %s\n", checkpoint_unsupported(opt).c_str());
    return kUsage;
  }
  std::optional<CompareSetup> compare;
  try {
    compare = resolve_compare(opt.compare, cfg, opt.until);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: invalid scene: %s\n", e.what());
    return kInvalidScene;
  }
  if ((opt.vtu || opt.splash || opt.hdf5) && opt.out.empty()) {
    std::fprintf(stderr, "sph: %s needs --out DIR (the files go beside the CSVs)\n",
                 opt.vtu ? "--vtu" : opt.splash ? "--splash" : "--hdf5");
    return kUsage;
  }
  if (opt.hdf5 && !hdf5_unsupported(cfg.params).empty()) {
    std::fprintf(stderr, "sph: --hdf5: scene %s: %s\n", cfg.scene->name.c_str(), hdf5_unsupported(cfg.params).c_str());
    return kUsage;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const double t_end = cfg.params.time.t_end;
  std::unique_ptr<World> world_ptr, b_ptr;  // outlive the try: a run that stops still reports its warnings
  try {
    const auto t0 = std::chrono::steady_clock::now();
    install_stop_handlers();  // from here a signal stops the run after a step (run_signals.h)
    world_ptr = std::make_unique<World>(cfg);
    if (resume) world_ptr->restore_state(resume->ck.world, "checkpoint " + resume->path);
    World& world = *world_ptr;
    if (compare) b_ptr = std::make_unique<World>(compare->b);
#ifdef SPH_HAVE_FRAMES
    std::unique_ptr<FrameRecorder> rec;
    RunOptions fopt = opt;  // with the colour-by field resolved
    try {
      if (!opt.frames.empty()) {  // refuse an unknown field before anything is written
        const Snapshot snap = world.report().snapshot();
        if (fopt.color_by.empty())  // the default: rho where the scene has it, else its first field
          fopt.color_by = snap.find("rho") || snap.fields.empty() ? "rho" : snap.fields.front().name;
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
        if (!snap.find(fopt.color_by))
          throw ConfigError("--color-by " + fopt.color_by + ": no such field in scene " + cfg.scene->name +
                            did_you_mean(fopt.color_by, names) + " (fields:" + known + ")");
        for (const std::string& p : render::panel_fields(snap, split_names(opt.panels)))
          if (!snap.find(p))
            throw ConfigError(std::string(flag::kPanels) + " " + opt.panels + ": no field '" + p + "' in scene " +
                              cfg.scene->name + did_you_mean(p, names) + " (fields:" + known +
                              "; v is vx in 1D, else speed)");
      }
      rec = make_recorder(fopt);  // validates the frame flags before anything is written
      if (rec && rec->view().profile_axis >= 0 && !render::draws_profile(cfg.scene->dim, rec->view().profile_axis))
        std::fprintf(stderr, "sph: note: %s applies to 2D scenes; %s is %dD, so it is ignored\n",
                     flag::kProfileAxis, cfg.scene->name.c_str(), cfg.scene->dim);
      if (rec && !opt.panels.empty() && !render::draws_profile(cfg.scene->dim, rec->view().profile_axis))
        std::fprintf(stderr, "sph: note: %s applies to profiles (1D scenes, or %s x|y|r); ignored\n", flag::kPanels,
                     flag::kProfileAxis);
    } catch (const ConfigError& e) {
      std::fprintf(stderr, "sph: %s\n", e.what());
      return kUsage;
    }
#else
    if (!opt.frames.empty() || !opt.video.empty()) {
      std::fprintf(stderr, "sph: --frames, --video: this build has no headless renderer\n");
      return kUsage;
    }
#endif
    std::unique_ptr<RunOutput> out, out_b;  // run B's files go to OUT/B
    OutputOptions formats{opt.csv_comments, opt.vtu, opt.splash, opt.hdf5};
    if (!opt.out.empty())
      out = resume ? std::make_unique<RunOutput>(opt.out, world, formats, resume->output)
                   : std::make_unique<RunOutput>(opt.out, world, formats);
    std::unique_ptr<Checkpointer> ck;  // also for the checkpoint a signal asks for (run_signals.h)
    if (checkpoint_unsupported(opt).empty()) ck = std::make_unique<Checkpointer>(opt, cfg, resume);
    if (!opt.out.empty() && b_ptr) out_b = std::make_unique<RunOutput>(opt.out + "/B", *b_ptr, formats);
    const double dt_out = cfg.params.time.dt_out > 0.0 ? cfg.params.time.dt_out : t_end;
    int next_out = resume ? resume->next_out : 1;
    if (out && !resume) { out->write_diagnostics(world); out->write_particles(world); }
    if (out_b) { out_b->write_diagnostics(*b_ptr); out_b->write_particles(*b_ptr); }
#ifdef SPH_HAVE_FRAMES
    int next_frame = 1;
    std::string err;
    Snapshot snap, snap_b;
    auto frame = [&] {  // the snapshot(s), with the probed particle's tree walk when asked for
      snap = world.report().snapshot();
      if (opt.tree_probe >= 0) {
        snap.tree_cells = world.report().tree_cells(static_cast<std::size_t>(opt.tree_probe));
        snap.tree_probe = opt.tree_probe;
      }
      render::FrameScene scene;
      scene.a = &snap;
      if (b_ptr) {
        snap_b = b_ptr->report().snapshot();
        scene.b = &snap_b;
        scene.label_a = compare->label_a;
        scene.label_b = compare->label_b;
        scene.errors_a = reference_errors(world);
        scene.errors_b = reference_errors(*b_ptr);
      }
      return scene;
    };
    if (rec && !rec->write_frame(frame(), &err)) throw IoError(err);
    Progress progress(t_end);
#endif
    auto reached = [&](double t) { return world.time() >= t * (1.0 - 1e-12); };
    while (world.time() < t_end) {
      double target = std::min(t_end, next_out * dt_out);
#ifdef SPH_HAVE_FRAMES
      if (rec) target = std::min(target, next_frame * opt.every);
#endif
      world.step(target - world.time());
      if (b_ptr) advance_b(*b_ptr, world.time(), *compare);
      if (out) out->write_diagnostics(world);
      if (out_b) out_b->write_diagnostics(*b_ptr);
      if (reached(next_out * dt_out) || world.time() >= t_end) {
        if (out) out->write_particles(world);
        if (out_b) out_b->write_particles(*b_ptr);
        while (reached(next_out * dt_out)) ++next_out;
      }
#ifdef SPH_HAVE_FRAMES
      if (rec && reached(next_frame * opt.every)) {
        if (!rec->write_frame(frame(), &err)) throw IoError(err);
        while (reached(next_frame * opt.every)) ++next_frame;
      }
      progress.update(world.time());
#endif
      if (ck && (ck->due(world.time()) || stop_signal() != 0)) ck->write(world, *out, next_out);
      if (stop_signal() != 0) return report_stop(stop_signal(), world, opt, ck != nullptr);
    }
#ifdef SPH_HAVE_FRAMES
    progress.finish();
#endif
    if (out) { out->write_warnings(world); out->finish(); }
    if (out_b) { out_b->write_warnings(*b_ptr); out_b->finish(); }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!opt.quiet) {
      const double psteps = static_cast<double>(world.steps()) * static_cast<double>(world.particles().size());
      std::printf("%s: t = %g after %lld steps, %zu particles, %.3f s wall, %.3g particle-steps/s, %d threads "
                  "(the last step on %d; idle threads: %s)\n",
                  cfg.scene->name.c_str(), world.time(), static_cast<long long>(world.steps()),
                  world.particles().size(), wall, psteps / wall, omp_get_max_threads(), world.last_team(),
                  thread_wait_policy().c_str());
      if (world.report().has_reference()) {
        const auto& cols = world.report().reference_columns();
        const std::vector<double> vals = world.report().reference_values();
        std::printf("reference at t = %g (%s):\n", world.time(), world.report().reference()->description().c_str());
        std::string line;
        for (std::size_t k = 0; k < cols.size(); ++k) {
          char item[96];
          std::snprintf(item, sizeof item, "  %s = %.6g", cols[k].name.c_str(), vals[k]);
          line += item;
        }
        std::printf("%s\n", line.c_str());
      }
      if (b_ptr) std::printf("%s\n", compare_summary(*b_ptr, *compare).c_str());
    }
    print_warnings(world);
    if (b_ptr) print_warnings(*b_ptr);
#ifdef SPH_HAVE_FRAMES
    if (rec) {
      if (!rec->flush(&err)) throw IoError(err);  // PNGs are compressed in the background
      std::printf("%d frames in %s; make a video with:\n  %s\n", rec->frames_written(), opt.frames.c_str(),
                  rec->ffmpeg_command().c_str());
      if (!opt.video.empty()) {
        if (!rec->make_video(&err)) {
          std::fprintf(stderr, "sph: %s\n", err.c_str());
          return kIoError;
        }
        std::printf("video %s (%d frames at %d/s), last frame %s\n", opt.video.c_str(), rec->frames_written(), opt.fps,
                    rec->still_path().c_str());
      }
    }
#endif
  } catch (const DivergedError& e) {
    std::fprintf(stderr, "sph: %s; the state was not written\n", e.what());
    if (world_ptr) print_warnings(*world_ptr);
    if (b_ptr) print_warnings(*b_ptr);
    return kDiverged;
  } catch (const IoError& e) {
    std::fprintf(stderr, "sph: I/O error: %s\n", e.what());
    return kIoError;
  } catch (const CheckpointError& e) {
    std::fprintf(stderr, "sph: %s\n", e.what());
    return kInvalidScene;
  }
  return kOk;
}

}  // namespace sph::cli

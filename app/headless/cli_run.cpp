#include "cli_run.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_common.h"
#include "cli_sweep.h"
#include "exit_codes.h"
#include "run_checkpoint.h"
#include "run_output.h"
#include "run_report.h"
#include "run_signals.h"
#include "sph/config.h"
#include "sph/ic_export.h"
#include "sph/memory_budget.h"
#include "sph/world.h"
#ifdef SPH_HAVE_FRAMES
#include "progress.h"
#include "run_frames.h"
#endif

namespace sph::cli {
namespace {

using Clock = std::chrono::steady_clock;

sph::RunConfig resolve(const RunOptions& opt) {
  sph::RunConfig cfg = sph::RunConfig::load(opt.scene);
  apply_sets(cfg, opt.sets);
  if (opt.until >= 0.0) cfg.params.time.t_end = opt.until;
  cfg.validate();
  check_run_memory(cfg);  // an enormous particle count is refused before anything is allocated
  return cfg;
}

/// The scene, the checkpoint continued, the comparison and the output flags checked before the run starts:
/// kOk, or the exit code after a message.
int prepare_run(const RunOptions& opt, const ResumePoint* resume, RunConfig* cfg_out,
                std::optional<CompareSetup>* compare, std::unique_ptr<SweepRuns>* sweep) {
  RunConfig& cfg = *cfg_out;
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
  // a sweep's form here (exit 2), its values against the scene below (exit 3)
  if (const std::string e = SweepRuns::usage_error(opt.sweep, !opt.compare.scene.empty() || !opt.compare.sets.empty());
      !e.empty()) {
    std::fprintf(stderr, "sph: --sweep: %s\n", e.c_str());
    return kUsage;
  }
  try {
    *compare = resolve_compare(opt.compare, cfg, opt.until);
    *sweep = SweepRuns::resolve(opt.sweep, cfg, opt.until);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: invalid scene: %s\n", e.what());
    return kInvalidScene;
  }
  if ((opt.vtu || opt.splash || opt.hdf5 || opt.probe_every > 0.0) && opt.out.empty()) {
    std::fprintf(stderr, "sph: %s needs --out DIR (the files go beside the CSVs)\n",
                 opt.vtu ? "--vtu" : opt.splash ? "--splash" : opt.hdf5 ? "--hdf5" : "--probe-every");
    return kUsage;
  }
  if (opt.probe_every > 0.0 && !cfg.scene->reference) {
    std::fprintf(stderr, "sph: --probe-every: scene %s has no reference (no errors.csv to write)\n", cfg.scene->name.c_str());
    return kUsage;
  }
  if (opt.hdf5 && !hdf5_unsupported(cfg.params).empty()) {
    std::fprintf(stderr, "sph: --hdf5: scene %s: %s\n", cfg.scene->name.c_str(), hdf5_unsupported(cfg.params).c_str());
    return kUsage;
  }
  return kOk;
}

/// Run B to run A's time; a divergence of B names it.
void advance_b(World& b, double t, const CompareSetup& setup) {
  try {
    b.advance_to(t);
  } catch (const DivergedError&) {
    std::fprintf(stderr, "sph: run %s diverged:\n", setup.label_b.c_str());
    throw;
  }
}

/// The world is at time t (to a relative 1e-12: a step that lands on t).
bool reached(const World& world, double t) { return world.time() >= t * (1.0 - 1e-12); }

/// The run's files: run A's output folder (--out), run B's (OUT/B), the checkpointer, the next output due.
struct RunFiles {
  std::unique_ptr<RunOutput> out, out_b;
  std::unique_ptr<Checkpointer> ck;  // also for the checkpoint a signal asks for (run_signals.h)
  double dt_out = 0.0, dt_probe = 0.0;  // dt_probe: --probe-every (0: errors.csv rows with the particles)
  int next_out = 1;
  long next_probe = 1;
  double next_due() const { return dt_probe > 0.0 ? std::min(next_out * dt_out, next_probe * dt_probe) : next_out * dt_out; }
};

/// Opens the run's files and writes the state at the start (a resumed run's files go on where they were).
void open_files(const RunOptions& opt, const ResumePoint* resume, const RunConfig& cfg, const World& world,
                const World* b, RunFiles& files) {
  OutputOptions formats{opt.csv_comments, opt.vtu, opt.splash, opt.hdf5, opt.probe_every > 0.0};
  if (!opt.out.empty())
    files.out = resume ? std::make_unique<RunOutput>(opt.out, world, formats, resume->output)
                       : std::make_unique<RunOutput>(opt.out, world, formats);
  if (checkpoint_unsupported(opt).empty()) files.ck = std::make_unique<Checkpointer>(opt, cfg, resume);
  if (!opt.out.empty() && b) files.out_b = std::make_unique<RunOutput>(opt.out + "/B", *b, formats);
  const double t_end = cfg.params.time.t_end;
  files.dt_out = cfg.params.time.dt_out > 0.0 ? cfg.params.time.dt_out : t_end;
  files.next_out = resume ? resume->next_out : 1;
  files.dt_probe = opt.probe_every;  // a resumed run's next probe follows from its time
  if (files.dt_probe > 0.0) files.next_probe = static_cast<long>(std::floor(world.time() / files.dt_probe * (1.0 + 1e-12))) + 1;
  if (files.out && !resume) { files.out->write_diagnostics(world); files.out->write_particles(world); }
  if (files.out && !resume && files.dt_probe > 0.0) files.out->write_errors(world);
  if (files.out_b) { files.out_b->write_diagnostics(*b); files.out_b->write_particles(*b); }
}

/// After a step: the diagnostics rows, and the particles when an output time (or the end) was reached.
/// `current` names the world being checked, for a divergence the check finds.
void write_step(RunFiles& files, World& world, World* b, double t_end, const World*& current) {
  const bool output = reached(world, files.next_out * files.dt_out) || world.time() >= t_end;
  if (output) {  // a gravity scene's energy checked at each output too (a blow-up is not written)
    world.check_output();
    if (b) { current = b; b->check_output(); current = &world; }
  }
  if (files.out) files.out->write_diagnostics(world);
  if (files.out_b) files.out_b->write_diagnostics(*b);
  if (output) {
    if (files.out) files.out->write_particles(world);
    if (files.out_b) files.out_b->write_particles(*b);
    while (reached(world, files.next_out * files.dt_out)) ++files.next_out;
  }
  if (files.dt_probe > 0.0 && (reached(world, files.next_probe * files.dt_probe) || world.time() >= t_end)) {
    if (files.out) files.out->write_errors(world);
    while (reached(world, files.next_probe * files.dt_probe)) ++files.next_probe;
  }
}

/// A run stopped by a divergence in its loop: the message, the warnings so far, and warnings.csv in each
/// output folder beside the files written so far, the diverged world's ending in a row of kind "diverged"
/// (RunOutput::write_warnings); kDiverged. An I/O error here is reported and the exit stays kDiverged.
int report_divergence(RunFiles& files, const World& world, const World* b, const World& culprit,
                      const DivergedError& e) {
  std::fprintf(stderr, "sph: %s; the state was not written%s\n", e.what(),
               files.out ? " (warnings.csv records the divergence)" : "");
  print_warnings(world);
  if (b) print_warnings(*b);
  try {
    if (files.out) files.out->write_warnings(world, &culprit == &world ? &e : nullptr);
    if (files.out_b) files.out_b->write_warnings(*b, &culprit == b ? &e : nullptr);
  } catch (const IoError& io) {
    std::fprintf(stderr, "sph: I/O error: %s\n", io.what());
  }
  return kDiverged;
}

/// The run once its worlds exist: the frames checked, the files opened, the steps to t_end with the files
/// and frames falling due, the summary; the exit code (a stop signal's after its checkpoint).
int run_worlds(const RunOptions& opt, const ResumePoint* resume, const RunConfig& cfg,
               const std::optional<CompareSetup>& compare, World& world, World* b, SweepRuns* sweep,
               Clock::time_point t0) {
#ifdef SPH_HAVE_FRAMES
  std::optional<RunFrames> frames;
  try {
    frames.emplace(opt, cfg, world, resume ? &resume->frames : nullptr);  // a bad flag refused before any file
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
  RunFiles files;
  open_files(opt, resume, cfg, world, b, files);
  const double t_end = cfg.params.time.t_end;
#ifdef SPH_HAVE_FRAMES
  if (frames->active() && !resume) frames->write(world, b, compare, sweep);  // a resumed sequence has its first frames
  Progress progress(t_end);
#endif
  const World* current = &world;  // the world a divergence comes from
  try {
    while (world.time() < t_end) {
      double target = std::min(t_end, files.next_due());
#ifdef SPH_HAVE_FRAMES
      if (frames->active()) target = std::min(target, frames->next_time());
#endif
      world.step(target - world.time());
#ifdef SPH_HAVE_FRAMES
      if (frames->active()) frames->record_trails(world);
#endif
      if (b) { current = b; advance_b(*b, world.time(), *compare); current = &world; }
      if (sweep) {  // to A's time, and at an output time their energies checked as A's
        sweep->advance_to(world.time(), current);
        if (reached(world, files.next_out * files.dt_out) || world.time() >= t_end) sweep->check_output(current);
      }
      write_step(files, world, b, t_end, current);
#ifdef SPH_HAVE_FRAMES
      if (frames->active() && reached(world, frames->next_time())) {
        frames->write(world, b, compare, sweep);
        while (reached(world, frames->next_time())) frames->advance();
      }
      progress.update(world.time());
#endif
      if (files.ck && (files.ck->due(world.time()) || stop_signal() != 0)) {
        FrameResume frame_state;
#ifdef SPH_HAVE_FRAMES
        frame_state = frames->resume_state();
#endif
        files.ck->write(world, *files.out, files.next_out, frame_state);
      }
      if (stop_signal() != 0) return report_stop(stop_signal(), world, opt, files.ck != nullptr);
    }
  } catch (const DivergedError& e) {
    if (sweep) sweep->print_warnings();
    return report_divergence(files, world, b, *current, e);
  }
#ifdef SPH_HAVE_FRAMES
  progress.finish();
#endif
  if (files.out) { files.out->write_warnings(world); files.out->finish(); }
  if (files.out_b) { files.out_b->write_warnings(*b); files.out_b->finish(); }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  print_summary(opt, cfg, world, b, compare, wall);
  if (sweep && !opt.quiet) sweep->print_summary();
  print_warnings(world);
  if (b) print_warnings(*b);
  if (sweep) sweep->print_warnings();
#ifdef SPH_HAVE_FRAMES
  if (const int rc = frames->finish(); rc != kOk) return rc;
#endif
  return energy_code(cfg, world, b, sweep && sweep->energy_beyond_bound());
}

}  // namespace

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
  std::optional<CompareSetup> compare;
  std::unique_ptr<SweepRuns> sweep;
  if (const int rc = prepare_run(opt, resume, &cfg, &compare, &sweep); rc != kOk) return rc;
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  std::unique_ptr<World> world_ptr, b_ptr;  // outlive the try: a run that stops still reports its warnings
  try {
    const auto t0 = Clock::now();
    install_stop_handlers();  // from here a signal stops the run after a step (run_signals.h)
    world_ptr = std::make_unique<World>(cfg);
    if (resume) world_ptr->restore_state(resume->ck.world, "checkpoint " + resume->path);
    if (compare) b_ptr = std::make_unique<World>(compare->b);
    if (sweep) sweep->build();
    return run_worlds(opt, resume, cfg, compare, *world_ptr, b_ptr.get(), sweep.get(), t0);
  } catch (const DivergedError& e) {
    std::fprintf(stderr, "sph: %s; the state was not written\n", e.what());  // before the run's files
    if (world_ptr) print_warnings(*world_ptr);
    if (b_ptr) print_warnings(*b_ptr);
    return kDiverged;
  } catch (const IoError& e) {
    std::fprintf(stderr, "sph: I/O error: %s\n", e.what());
    return kIoError;
  } catch (const CheckpointError& e) {
    std::fprintf(stderr, "sph: %s\n", e.what());
    return kInvalidScene;
  } catch (const ConfigError& e) {  // a scene that cannot place its particles from these values
    std::fprintf(stderr, "sph: invalid scene: %s: %s\n", cfg.scene ? cfg.scene->name.c_str() : "scene", e.what());
    return kInvalidScene;
  }
}

}  // namespace sph::cli

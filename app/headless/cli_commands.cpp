// The subcommands of `sph` and their options (CLI11), in the order of `sph --help`, and the dispatch to the
// chosen one.
#include "cli_commands.h"

#include "cli_assets.h"
#include "cli_help.h"
#include "cli_resume.h"
#include "number_checks.h"

namespace sph::cli {
namespace {

/// `sph check` and `sph run`: the scene, its overrides and end time; run's outputs and checkpoints.
void add_run_options(CLI::App* check, CLI::App* run, CommandLine& cl) {
  for (auto* sub : {check, run}) {
    sub->add_option("scene", cl.run.scene, "built-in scene name, JSON scene file or HDF5 initial condition (.hdf5)")
        ->required();
    sub->add_option("--set", cl.run.sets, "override a parameter: key=value (repeatable; `sph help SCENE` lists the keys)");
    sub->add_option("--until", cl.run.until, "end time (overrides time.t_end)")->check(finite_from(0.0, false));
  }
  run->add_option("--out", cl.run.out, "output directory: scene.json, diagnostics.csv, particles_*.csv, errors.csv, csv_meta.json");
  run->add_option("--threads", cl.run.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  run->add_flag("--quiet", cl.run.quiet, "no summary line");
  run->add_option("--probe-every", cl.run.probe_every,
                  "simulated time between the rows of errors.csv (the reference's probes and errors), instead of one "
                  "row per particle output: a fine time series without the particle files (needs --out)")
      ->check(finite_from(0.0, true));
  run->add_option("--checkpoint-every", cl.run.checkpoint_every,
                  "simulated time between checkpoints OUT/checkpoint.sph (needs --out; `sph resume OUT` continues "
                  "the run bitwise as if it had not stopped)")
      ->check(finite_from(0.0, true));
}

/// `sph resume DIR`: a run continued from its checkpoint.
void add_resume_command(CLI::App& app, CommandLine& cl) {
  auto* resume = app.add_subcommand("resume", "continue a run stopped at its checkpoint DIR/checkpoint.sph (a signal, "
                                              "--checkpoint-every) with the options it was started with");
  resume->add_option("dir", cl.resume_dir, "the --out DIR of the run")->required();
  resume->add_flag("--quiet", cl.resume_quiet, "no summary line");
  resume->add_option("--until", cl.resume_until, "a new end time (default: the run's own)")->check(finite_from(0.0, false));
  resume->add_option("--threads", cl.resume_threads, "OpenMP threads (results do not depend on them)")
      ->check(CLI::Range(1, 1024));
}

/// `sph run`'s A/B comparison and particle formats.
void add_compare_options(CLI::App* run, CommandLine& cl) {
  run->add_option("--compare", cl.run.compare.scene,
                  "A/B comparison: run B is this scene name or JSON file (the same scene as A, other parameters), "
                  "stepped to A's times; its files go to OUT/B, its frames beside A's");
  run->add_option("--compare-set", cl.run.compare.sets,
                  "A/B comparison: run B is run A (or --compare's scene) with key=value changed (repeatable), "
                  "e.g. --compare-set kernel.type=M6");
  run->add_option("--sweep", cl.run.sweep,
                  "a parameter sweep: run A beside one more run per value, KEY=V1,V2,... (at most 5), e.g. "
                  "kernel.eta=1.0,1.5; every profile frame draws all runs; the summary lists each run's errors");
  run->add_flag("--csv-comments", cl.run.csv_comments, "keep the '#' comment lines in the CSV files (default: in csv_meta.json)");
  run->add_flag("--vtu", cl.run.vtu, "also write particles_NNNNN.vtu and particles.pvd (ParaView)");
  run->add_flag("--splash", cl.run.splash, "also write particles_NNNNN.dat (SPLASH: splash -ascii FILE)");
  run->add_flag("--hdf5", cl.run.hdf5, "also write particles_NNNNN.hdf5 (the SWIFT/GADGET layout)");
}

#ifdef SPH_HAVE_FRAMES
/// `sph run`'s frames (headless renderer: image sequences, videos).
void add_frame_options(CLI::App* run, CommandLine& cl) {
  run->add_option("--frames", cl.run.frames, "write PNG frames into this directory");
  run->add_option("--every", cl.run.every, "simulated time between frames")->check(finite_from(0.0, true));
  run->add_option("--size", cl.run.size, "frame size WIDTHxHEIGHT (even numbers)");
  run->add_option("--color-by", cl.run.color_by, "field to colour by (rho, p, u, speed, h, vx, ...; default rho, or the scene's first field)");
  run->add_option("--cmap", cl.run.cmap, "colour map: viridis, magma, cividis, coolwarm");
  run->add_option("--range", cl.run.range, "colour range: auto (min..max), pLO:HI (between percentiles, e.g. p1:99 as the GUI) or MIN:MAX (in log10 units with --log)");
  run->add_flag("--log", cl.run.log_scale, "colour by log10 of the field (values <= 0 are not drawn)");
  run->add_flag("--linear", cl.run.linear,
                "plane and 3D views: a linear colour scale even for a field spanning more than two decades "
                "(by default such a field is coloured by log10)");
  run->add_flag("--residuals", cl.run.residuals,
                "profiles with an exact curve: a strip of the values minus the exact ones under each panel (a "
                "comparison always has one: B - A in 1D)");
  run->add_flag("--high-contrast", cl.run.high_contrast,
                "frames with white-on-black axes, labels and legends (as sph-gui --high-contrast, for a projector)");
  run->add_flag("--hide-walls", cl.run.hide_walls,
                "2D and 3D frames without the wall particles (a 3D tank's walls hide its water; the GUI's 'show walls')");
  run->add_option("--cut", cl.run.cut, "3D scenes: a cutaway, only the particles with AXIS <= VALUE drawn, e.g. z=0");
  run->add_option("--profile-axis", cl.run.profile_axis,
                  "2D scenes: plot the field against x or y (with its reference curve) instead of the plane; off");
  run->add_option("--video", cl.run.video, "also make this .mp4, .webm or .gif with ffmpeg, and VIDEO_last.png (frames go to "
                                        "--frames, else VIDEO_frames/)");
  run->add_option("--fps", cl.run.fps, "frame rate of --video")->check(CLI::Range(1, 240));
  run->add_option("--gl", cl.run.gl, "off-screen OpenGL: osmesa, egl or auto (default: $SPH_GL, else auto = OSMesa, then EGL)");
  run->add_option("--panels", cl.run.panels,
                  "profiles (1D, or --profile-axis): one panel per field, comma-separated, e.g. rho,v,p,u (v: v_x in 1D)");
  run->add_option("--tree-probe", cl.run.tree_probe,
                  "scenes with physics.gravity = tree: draw the cells of this particle's tree walk in the frames")
      ->check(CLI::NonNegativeNumber);
}
#endif

/// `sph converge` and `sph bench`: the studies over resolutions (and kernels, integrators).
void add_study_commands(CLI::App& app, CommandLine& cl) {
  auto* converge = app.add_subcommand("converge", "convergence study: error against resolution, with observed orders");
  converge->add_option("scene", cl.converge.scene, "built-in scene name or JSON scene file (it must have a reference)")->required();
  converge->add_option("--key", cl.converge.key, "parameter varied (default: the scene's, e.g. scene.n)");
  converge->add_option("--values", cl.converge.values, "comma-separated values of the key (default: the scene's)");
  converge->add_option("--until", cl.converge.until, "time of the comparison (default: the scene's)")
      ->check(finite_from(0.0, true));
  converge->add_option("--column", cl.converge.column, "reference column compared (default: the primary error)");
  converge->add_option("--set", cl.converge.sets, "override a parameter of every run: key=value (repeatable)");
  converge->add_option("--out", cl.converge.out, "output directory (default converge_SCENE): converge.csv, .md, .png");
  converge->add_option("--threads", cl.converge.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  converge->add_option("--size", cl.converge.size, "plot size WIDTHxHEIGHT (even numbers)");
  converge->add_flag("--quiet", cl.converge.quiet, "no progress or table on the terminal");
  converge->add_flag("--csv-comments", cl.converge.csv_comments, "a '#' line naming the study at the head of converge.csv");
  auto* bench = app.add_subcommand("bench", "work-precision report: error against wall time over resolutions x kernels x integrators");
  bench->add_option("scenes", cl.bench.scenes, "scenes with a reference (default: sod, shocktube_castellanos, toro3, sedov)");
  bench->add_option("--values", cl.bench.values, "comma-separated values of each scene's study key (default: the scene's)");
  bench->add_option("--kernels", cl.bench.kernels, "comma-separated kernels (default: M4,M6,wendland_c2; N-body and FPM scenes keep theirs)");
  bench->add_option("--integrators", cl.bench.integrators, "comma-separated integrators (default: leapfrog,rk4)");
  bench->add_option("--set", cl.bench.sets, "override a parameter of every run: key=value (repeatable)");
  bench->add_option("--out", cl.bench.out, "output directory (default bench): bench.csv, bench.md, bench_SCENE.png");
  bench->add_option("--threads", cl.bench.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  bench->add_option("--size", cl.bench.size, "plot size WIDTHxHEIGHT (even numbers)");
  bench->add_flag("--quiet", cl.bench.quiet, "no progress or table on the terminal");
  bench->add_flag("--csv-comments", cl.bench.csv_comments, "a '#' line at the head of bench.csv");
}

/// `sph export-ics`, `help`, `params`, `lesson`, `scene-json`, `write-assets`.
void add_tool_commands(CLI::App& app, CommandLine& cl) {
  auto* exp = app.add_subcommand("export-ics", "write a scene's initial condition for SWIFT or GADGET-4 (HDF5) and "
                                               "the parameter file to run it");
  exp->add_option("scene", cl.export_ics.scene, "built-in scene name, JSON scene file or HDF5 initial condition")->required();
  exp->add_option("--format", cl.export_ics.format, "swift (FILE.yml beside it) or gadget4 (FILE-param.txt)");
  exp->add_option("--out", cl.export_ics.out, "the .hdf5 file to write")->required();
  exp->add_option("--set", cl.export_ics.sets, "override a parameter: key=value (repeatable)");
  exp->add_option("--until", cl.export_ics.until, "end time written to the parameter file")->check(finite_from(0.0, true));
  exp->add_option("--threads", cl.export_ics.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  auto* help = app.add_subcommand("help", "explain a scene: stages, every parameter (unit, range, default, seed "
                                          "equation), its reference and error norms; without one, list the scenes");
  help->add_option("scene", cl.help_scene, "built-in scene name, JSON scene file or HDF5 initial condition");
  help->add_option("--set", cl.help_sets, "show the scene with these overrides: key=value (repeatable)");
  app.add_subcommand("params", "every run parameter key with its unit, range, default and stage");
  auto* lesson = app.add_subcommand("lesson", "a lesson (assets/lessons/*.json): show prints its steps, check runs every "
                                              "step's claim headless (exit 6 malformed file, 7 a false claim)");
  lesson->add_option("action", cl.lesson.action, "show or check")->required()->check(CLI::IsMember({"show", "check"}));
  lesson->add_option("file", cl.lesson.file, "the lesson's JSON file")->required();
  lesson->add_option("--threads", cl.lesson.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  auto* scene_json = app.add_subcommand("scene-json", "print the scene file of a built-in scene at its compiled defaults "
                                                      "(assets/scenes/NAME.json; exit 3 for an unknown name)");
  scene_json->add_option("name", cl.scene_json_name, "built-in scene name")->required();
  auto* write_assets = app.add_subcommand("write-assets", "write DIR/NAME.json for every built-in scene at its compiled "
                                                          "defaults (regenerates assets/scenes; exit 4 if DIR is not "
                                                          "a writable folder)");
  write_assets->add_option("dir", cl.assets_dir, "the folder, e.g. assets/scenes")->required();
}

}  // namespace

void add_commands(CLI::App& app, CommandLine& cl) {
  app.add_subcommand("list", "list the built-in scenes");
  auto* check = app.add_subcommand("check", "validate a scene name or JSON file and its overrides");
  auto* run = app.add_subcommand("run", "run a scene and write its output");
  add_run_options(check, run, cl);
  add_compare_options(run, cl);
  add_resume_command(app, cl);  // listed after run, before converge
#ifdef SPH_HAVE_FRAMES
  add_frame_options(run, cl);
#endif
  add_study_commands(app, cl);
  add_tool_commands(app, cl);
}

int run_subcommand(const CLI::App& app, const CommandLine& cl) {
  if (app.got_subcommand("list")) return list_command();
  if (app.got_subcommand("check")) return check_command(cl.run);
  if (app.got_subcommand("converge")) return converge_command(cl.converge);
  if (app.got_subcommand("bench")) return bench_command(cl.bench);
  if (app.got_subcommand("export-ics")) return export_command(cl.export_ics);
  if (app.got_subcommand("help")) return help_command(cl.help_scene, cl.help_sets);
  if (app.got_subcommand("params")) return params_command();
  if (app.got_subcommand("resume")) return resume_command(cl.resume_dir, cl.resume_threads, cl.resume_until, cl.resume_quiet);
  if (app.got_subcommand("lesson")) return lesson_command(cl.lesson);
  if (app.got_subcommand("scene-json")) return scene_json_command(cl.scene_json_name);
  if (app.got_subcommand("write-assets")) return write_assets_command(cl.assets_dir);
  return run_command(cl.run);
}

}  // namespace sph::cli

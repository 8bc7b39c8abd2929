// sph: the headless program. `sph list`, `sph check SCENE`, `sph run SCENE [...]`, `sph converge SCENE [...]`,
// `sph bench [SCENE...]`, `sph export-ics SCENE`, `sph help [SCENE]`, `sph params`, `sph lesson show|check FILE`,
// `sph scene-json NAME`, `sph write-assets DIR`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "cli_assets.h"
#include "cli_bench.h"
#include "cli_converge.h"
#include "cli_export.h"
#include "cli_help.h"
#include "cli_resume.h"
#include "cli_lesson.h"
#include "cli_run.h"
#include "cli_suggest.h"
#include "exit_codes.h"
#include "parse_command_line.h"
#include "number_checks.h"
#include "sph/thread_wait.h"

int main(int argc, char** argv) {
  sph::prefer_brief_spinning(argv);  // before any OpenMP use (sph/thread_wait.h)
  using namespace sph::cli;
  CLI::App app{"sph: SPH sandbox, headless runs. `sph help SCENE` explains a scene, `sph params` every key.\n"
               "Exit codes: 0 ok, 1 internal error, 2 usage error, 3 invalid scene (unknown scene, malformed\n"
               "file, unknown key, value out of range), 4 I/O error, 5 diverged (NaN/inf in the state, a\n"
               "finite blow-up of the energy or the timestep, a particle through a wall, a start the h solve\n"
               "cannot reach), 6 malformed lesson file (sph lesson), 7 a lesson's claim is false (sph lesson\n"
               "check), 130/143 stopped by SIGINT/SIGTERM after a step with a checkpoint written\n"
               "(continue with `sph resume DIR`; a second signal stops at once). 3 also: a checkpoint that is\n"
               "missing, truncated, damaged, of another version or not one. What a run tolerated is listed\n"
               "under \"warnings\" (and in warnings.csv)."};
  app.require_subcommand(1);
  RunOptions opt;
  app.add_subcommand("list", "list the built-in scenes");
  auto* check = app.add_subcommand("check", "validate a scene name or JSON file and its overrides");
  auto* run = app.add_subcommand("run", "run a scene and write its output");
  for (auto* sub : {check, run}) {
    sub->add_option("scene", opt.scene, "built-in scene name, JSON scene file or HDF5 initial condition (.hdf5)")
        ->required();
    sub->add_option("--set", opt.sets, "override a parameter: key=value (repeatable; `sph help SCENE` lists the keys)");
    sub->add_option("--until", opt.until, "end time (overrides time.t_end)")->check(finite_from(0.0, false));
  }
  run->add_option("--out", opt.out, "output directory: scene.json, diagnostics.csv, particles_*.csv, errors.csv, csv_meta.json");
  run->add_option("--threads", opt.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  run->add_flag("--quiet", opt.quiet, "no summary line");
  run->add_option("--checkpoint-every", opt.checkpoint_every,
                  "simulated time between checkpoints OUT/checkpoint.sph (needs --out; `sph resume OUT` continues "
                  "the run bitwise as if it had not stopped)")
      ->check(finite_from(0.0, true));
  std::string resume_dir;
  int resume_threads = 0;
  double resume_until = -1.0;
  bool resume_quiet = false;
  auto* resume = app.add_subcommand("resume", "continue a run stopped at its checkpoint DIR/checkpoint.sph (a signal, "
                                              "--checkpoint-every) with the options it was started with");
  resume->add_option("dir", resume_dir, "the --out DIR of the run")->required();
  resume->add_flag("--quiet", resume_quiet, "no summary line");
  resume->add_option("--until", resume_until, "a new end time (default: the run's own)")->check(finite_from(0.0, false));
  resume->add_option("--threads", resume_threads, "OpenMP threads (results do not depend on them)")
      ->check(CLI::Range(1, 1024));
  run->add_option("--compare", opt.compare.scene,
                  "A/B comparison: run B is this scene name or JSON file (the same scene as A, other parameters), "
                  "stepped to A's times; its files go to OUT/B, its frames beside A's");
  run->add_option("--compare-set", opt.compare.sets,
                  "A/B comparison: run B is run A (or --compare's scene) with key=value changed (repeatable), "
                  "e.g. --compare-set kernel.type=M6");
  run->add_flag("--csv-comments", opt.csv_comments, "keep the '#' comment lines in the CSV files (default: in csv_meta.json)");
  run->add_flag("--vtu", opt.vtu, "also write particles_NNNNN.vtu and particles.pvd (ParaView)");
  run->add_flag("--splash", opt.splash, "also write particles_NNNNN.dat (SPLASH: splash -ascii FILE)");
  run->add_flag("--hdf5", opt.hdf5, "also write particles_NNNNN.hdf5 (the SWIFT/GADGET layout)");
#ifdef SPH_HAVE_FRAMES  // headless renderer: image sequences
  run->add_option("--frames", opt.frames, "write PNG frames into this directory");
  run->add_option("--every", opt.every, "simulated time between frames")->check(finite_from(0.0, true));
  run->add_option("--size", opt.size, "frame size WIDTHxHEIGHT (even numbers)");
  run->add_option("--color-by", opt.color_by, "field to colour by (rho, p, u, speed, h, vx, ...; default rho, or the scene's first field)");
  run->add_option("--cmap", opt.cmap, "colour map: viridis, magma, cividis, coolwarm");
  run->add_option("--range", opt.range, "colour range: auto (min..max), pLO:HI (between percentiles, e.g. p1:99 as the GUI) or MIN:MAX (in log10 units with --log)");
  run->add_flag("--log", opt.log_scale, "colour by log10 of the field (values <= 0 are not drawn)");
  run->add_option("--profile-axis", opt.profile_axis,
                  "2D scenes: plot the field against x or y (with its reference curve) instead of the plane; off");
  run->add_option("--video", opt.video, "also make this .mp4, .webm or .gif with ffmpeg, and VIDEO_last.png (frames go to "
                                        "--frames, else VIDEO_frames/)");
  run->add_option("--fps", opt.fps, "frame rate of --video")->check(CLI::Range(1, 240));
  run->add_option("--gl", opt.gl, "off-screen OpenGL: osmesa, egl or auto (default: $SPH_GL, else auto = OSMesa, then EGL)");
  run->add_option("--panels", opt.panels,
                  "profiles (1D, or --profile-axis): one panel per field, comma-separated, e.g. rho,v,p,u (v: v_x in 1D)");
  run->add_option("--tree-probe", opt.tree_probe,
                  "scenes with physics.gravity = tree: draw the cells of this particle's tree walk in the frames")
      ->check(CLI::NonNegativeNumber);
#endif
  ConvergeOptions conv;
  auto* converge = app.add_subcommand("converge", "convergence study: error against resolution, with observed orders");
  converge->add_option("scene", conv.scene, "built-in scene name or JSON scene file (it must have a reference)")->required();
  converge->add_option("--key", conv.key, "parameter varied (default: the scene's, e.g. scene.n)");
  converge->add_option("--values", conv.values, "comma-separated values of the key (default: the scene's)");
  converge->add_option("--until", conv.until, "time of the comparison (default: the scene's)")
      ->check(finite_from(0.0, true));
  converge->add_option("--column", conv.column, "reference column compared (default: the primary error)");
  converge->add_option("--set", conv.sets, "override a parameter of every run: key=value (repeatable)");
  converge->add_option("--out", conv.out, "output directory (default converge_SCENE): converge.csv, .md, .png");
  converge->add_option("--threads", conv.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  converge->add_option("--size", conv.size, "plot size WIDTHxHEIGHT (even numbers)");
  converge->add_flag("--quiet", conv.quiet, "no progress or table on the terminal");
  converge->add_flag("--csv-comments", conv.csv_comments, "a '#' line naming the study at the head of converge.csv");
  BenchOptions bench_opt;
  auto* bench = app.add_subcommand("bench", "work-precision report: error against wall time over resolutions x kernels x integrators");
  bench->add_option("scenes", bench_opt.scenes, "scenes with a reference (default: sod, shocktube_castellanos, toro3, sedov)");
  bench->add_option("--values", bench_opt.values, "comma-separated values of each scene's study key (default: the scene's)");
  bench->add_option("--kernels", bench_opt.kernels, "comma-separated kernels (default: M4,M6,wendland_c2; N-body and FPM scenes keep theirs)");
  bench->add_option("--integrators", bench_opt.integrators, "comma-separated integrators (default: leapfrog,rk4)");
  bench->add_option("--set", bench_opt.sets, "override a parameter of every run: key=value (repeatable)");
  bench->add_option("--out", bench_opt.out, "output directory (default bench): bench.csv, bench.md, bench_SCENE.png");
  bench->add_option("--threads", bench_opt.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  bench->add_option("--size", bench_opt.size, "plot size WIDTHxHEIGHT (even numbers)");
  bench->add_flag("--quiet", bench_opt.quiet, "no progress or table on the terminal");
  bench->add_flag("--csv-comments", bench_opt.csv_comments, "a '#' line at the head of bench.csv");
  ExportOptions ex;
  auto* exp = app.add_subcommand("export-ics", "write a scene's initial condition for SWIFT or GADGET-4 (HDF5) and "
                                               "the parameter file to run it");
  exp->add_option("scene", ex.scene, "built-in scene name, JSON scene file or HDF5 initial condition")->required();
  exp->add_option("--format", ex.format, "swift (FILE.yml beside it) or gadget4 (FILE-param.txt)");
  exp->add_option("--out", ex.out, "the .hdf5 file to write")->required();
  exp->add_option("--set", ex.sets, "override a parameter: key=value (repeatable)");
  exp->add_option("--until", ex.until, "end time written to the parameter file")->check(finite_from(0.0, true));
  exp->add_option("--threads", ex.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  std::string help_scene;
  std::vector<std::string> help_sets;
  auto* help = app.add_subcommand("help", "explain a scene: stages, every parameter (unit, range, default, seed "
                                          "equation), its reference and error norms; without one, list the scenes");
  help->add_option("scene", help_scene, "built-in scene name, JSON scene file or HDF5 initial condition");
  help->add_option("--set", help_sets, "show the scene with these overrides: key=value (repeatable)");
  app.add_subcommand("params", "every run parameter key with its unit, range, default and stage");
  LessonOptions lesson_opt;
  auto* lesson = app.add_subcommand("lesson", "a lesson (assets/lessons/*.json): show prints its steps, check runs every "
                                              "step's claim headless (exit 6 malformed file, 7 a false claim)");
  lesson->add_option("action", lesson_opt.action, "show or check")->required()->check(CLI::IsMember({"show", "check"}));
  lesson->add_option("file", lesson_opt.file, "the lesson's JSON file")->required();
  lesson->add_option("--threads", lesson_opt.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  std::string scene_json_name, assets_dir;
  auto* scene_json = app.add_subcommand("scene-json", "print the scene file of a built-in scene at its compiled defaults "
                                                      "(assets/scenes/NAME.json; exit 3 for an unknown name)");
  scene_json->add_option("name", scene_json_name, "built-in scene name")->required();
  auto* write_assets = app.add_subcommand("write-assets", "write DIR/NAME.json for every built-in scene at its compiled "
                                                          "defaults (regenerates assets/scenes; exit 4 if DIR is not "
                                                          "a writable folder)");
  write_assets->add_option("dir", assets_dir, "the folder, e.g. assets/scenes")->required();
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) sub->allow_extras();

  if (report_unknown_command(app, argc, argv)) return kUsage;
  if (const auto code = sph::parse_command_line(app, argc, argv, kUsage)) return *code;
  if (report_stray_arguments(app)) return kUsage;
  if (!opt.video.empty() && opt.frames.empty()) {  // frames beside the video: NAME_frames/
    const std::filesystem::path v(opt.video);
    opt.frames = (v.parent_path() / (v.stem().string() + "_frames")).string();
  }
  try {
    if (app.got_subcommand("list")) return list_command();
    if (app.got_subcommand("check")) return check_command(opt);
    if (app.got_subcommand("converge")) return converge_command(conv);
    if (app.got_subcommand("bench")) return bench_command(bench_opt);
    if (app.got_subcommand("export-ics")) return export_command(ex);
    if (app.got_subcommand("help")) return help_command(help_scene, help_sets);
    if (app.got_subcommand("params")) return params_command();
    if (app.got_subcommand("resume")) return resume_command(resume_dir, resume_threads, resume_until, resume_quiet);
    if (app.got_subcommand("lesson")) return lesson_command(lesson_opt);
    if (app.got_subcommand("scene-json")) return scene_json_command(scene_json_name);
    if (app.got_subcommand("write-assets")) return write_assets_command(assets_dir);
    return run_command(opt);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph: internal error: %s\n", e.what());
    return kInternal;
  }
}

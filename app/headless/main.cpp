// sph: the headless program. `sph list`, `sph check SCENE`, `sph run SCENE [...]`, `sph converge SCENE [...]`,
// `sph bench [SCENE...]`, `sph export-ics SCENE`, `sph help [SCENE]`, `sph params`, `sph lesson show|check FILE`,
// `sph scene-json NAME`, `sph write-assets DIR`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "cli_commands.h"
#include "cli_suggest.h"
#include "exit_codes.h"
#include "parse_command_line.h"
#include "sph/thread_wait.h"

int main(int argc, char** argv) {
  sph::prefer_brief_spinning(argv);  // before any OpenMP use (sph/thread_wait.h)
  using namespace sph::cli;
  CLI::App app{"sph: SPH sandbox, headless runs. `sph help SCENE` explains a scene, `sph params` every key.\n"
               "Exit codes: 0 ok, 1 internal error, 2 usage error, 3 invalid scene (unknown scene, malformed\n"
               "file, unknown key, value out of range), 4 I/O error, 5 diverged (NaN/inf in the state, a\n"
               "finite blow-up of the energy or the timestep, a particle through a wall, a start the h solve\n"
               "cannot reach), 6 malformed lesson file (sph lesson), 7 a lesson's claim is false (sph lesson\n"
               "check), 8 inaccurate: a gravity scene's energy drifted beyond its bound (the outputs and the\n"
               "warning are written), 130/143 stopped by SIGINT/SIGTERM after a step with a checkpoint written\n"
               "(continue with `sph resume DIR`; a second signal stops at once). 3 also: a checkpoint that is\n"
               "missing, truncated, damaged, of another version or not one. What a run tolerated is listed\n"
               "under \"warnings\" (and in warnings.csv)."};
  app.require_subcommand(1);
  CommandLine cl;
  add_commands(app, cl);
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) sub->allow_extras();

  if (report_unknown_command(app, argc, argv)) return kUsage;
  if (const auto code = sph::parse_command_line(app, argc, argv, kUsage)) return *code;
  if (report_stray_arguments(app)) return kUsage;
  if (!cl.run.video.empty() && cl.run.frames.empty()) {  // frames beside the video: NAME_frames/
    const std::filesystem::path v(cl.run.video);
    cl.run.frames = (v.parent_path() / (v.stem().string() + "_frames")).string();
  }
  try {
    return run_subcommand(app, cl);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph: internal error: %s\n", e.what());
    return kInternal;
  }
}

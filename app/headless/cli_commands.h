// The command line of `sph`: every subcommand with its options, bound to one struct of what they fill in,
// and the subcommand that was chosen run.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli_bench.h"
#include "cli_converge.h"
#include "cli_export.h"
#include "cli_lesson.h"
#include "cli_run.h"

namespace sph::cli {

/// What the command line fills in, one member (or group) per subcommand.
struct CommandLine {
  RunOptions run;  ///< check, run
  std::string resume_dir;
  int resume_threads = 0;
  double resume_until = -1.0;
  bool resume_quiet = false;
  ConvergeOptions converge;
  BenchOptions bench;
  ExportOptions export_ics;
  std::string help_scene;
  std::vector<std::string> help_sets;
  LessonOptions lesson;
  std::string scene_json_name, assets_dir;
};

/// Adds every subcommand with its options to app, bound to cl (in the order `sph --help` lists them).
void add_commands(CLI::App& app, CommandLine& cl);

/// Runs the subcommand app parsed (`run` when none of the others); its exit code.
int run_subcommand(const CLI::App& app, const CommandLine& cl);

}  // namespace sph::cli

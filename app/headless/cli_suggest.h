// Unknown commands and flags answered with the nearest valid one ("did you mean --vtu?").
#pragma once
#include <CLI/CLI.hpp>

namespace sph::cli {

/// argv[1] names no subcommand of app (and is not a flag): prints "unknown command" with the nearest
/// one and returns true.
bool report_unknown_command(const CLI::App& app, int argc, char** argv);

/// After a parse with extras allowed on the subcommands: the first argument the used subcommand did
/// not take, with its nearest flag; prints it and returns true if there is one.
bool report_stray_arguments(CLI::App& app);

}  // namespace sph::cli

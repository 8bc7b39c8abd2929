// Helpers shared by the subcommands: --set overrides, comma-separated lists of numbers or names, the
// output folder. (Whole files are written atomically through sph/atomic_file.h.)
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sph/config.h"

namespace sph::cli {

/// "60,120,240" -> {60, 120, 240}; empty items are skipped. Throws ConfigError naming `flag` and the
/// item that is not a finite number.
std::vector<double> parse_number_list(const std::string& text, const std::string& flag);
/// "M4,M6" -> {"M4", "M6"}; empty items are skipped.
std::vector<std::string> split_names(const std::string& text);
/// Applies --set key=value overrides in order; throws ConfigError naming the flag.
void apply_sets(RunConfig& cfg, const std::vector<std::string>& sets);
/// Creates dir (and parents); false if it cannot be made a folder. *existed: it was there before (a
/// folder made here is removed again when the command ends before writing into it).
bool make_output_dir(const std::filesystem::path& dir, bool* existed);
/// Runs `work` (a study's runs): a ConfigError or DivergedError is reported as "sph: COMMAND: ...", the
/// folder is removed again if the command made it (nothing was written yet), and the exit code (3, 5)
/// returned; 0 when the work completed.
int guarded_runs(const char* command, const std::filesystem::path& dir, bool existed, const std::function<void()>& work);
/// Parses --size WIDTHxHEIGHT of a plot; prints the usage message and returns false when malformed.
bool parse_plot_size(const std::string& size, int* width, int* height);

}  // namespace sph::cli

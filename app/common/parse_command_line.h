// The command-line parse both programs share: CLI11's --help prints the help and exits 0, a malformed
// command line prints CLI11's message and exits with the program's usage code.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>

namespace sph {

/// Parses argv into app: nullopt to go on, else the code to exit with (CLI11 printed the help or the
/// error; usage_code for an error).
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, int usage_code) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return usage_code;
  }
  return std::nullopt;
}

}  // namespace sph

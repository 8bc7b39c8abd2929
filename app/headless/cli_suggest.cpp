#include "cli_suggest.h"

#include <cstdio>
#include <string>
#include <vector>

#include "sph/suggest.h"

namespace sph::cli {

bool report_unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  const std::string word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == word) return false;
    names.push_back(sub->get_name());
  }
  std::string list;
  for (const std::string& n : names) list += " " + n;
  std::fprintf(stderr, "sph: unknown command '%s'%s (commands:%s; sph --help)\n", word.c_str(),
               did_you_mean(word, names).c_str(), list.c_str());
  return true;
}

bool report_stray_arguments(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands()) {  // the subcommands that were used
    const std::vector<std::string> stray = sub->remaining();
    if (stray.empty()) continue;
    std::vector<std::string> flags;
    for (const CLI::Option* o : sub->get_options()) {
      for (const std::string& n : o->get_lnames()) flags.push_back("--" + n);
    }
    const std::string& first = stray.front();
    const bool is_flag = first.starts_with("-");
    const std::string word = first.substr(0, first.find('='));
    std::fprintf(stderr, "sph %s: %s '%s'%s (sph %s --help lists them)\n", sub->get_name().c_str(),
                 is_flag ? "unknown flag" : "unexpected argument", first.c_str(),
                 is_flag ? did_you_mean(word, flags).c_str() : "", sub->get_name().c_str());
    return true;
  }
  return false;
}

}  // namespace sph::cli

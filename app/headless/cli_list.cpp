// `sph list`: every built-in scene with its dimension and description, the seed documents cited.
#include <cstdio>
#include <string>

#include "cli_run.h"
#include "exit_codes.h"
#include "sph/scene.h"
#include "sph/seed_documents.h"

namespace sph::cli {

int list_command() {
  std::string text;
  for (const auto& s : scene_registry()) {
    char head[40];
    std::snprintf(head, sizeof head, "%-24s %dD  ", s.name.c_str(), s.dim);
    text += head + s.description + "\n";
  }
  std::fputs(with_seed_citations(text).c_str(), stdout);
  return kOk;
}

}  // namespace sph::cli

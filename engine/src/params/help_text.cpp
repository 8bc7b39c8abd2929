// `sph params`, `sph help`: text built from the parameter table and the scene table (the help of one
// scene, which lists the stages its pipeline runs, is world/scene_help.cpp).
#include "sph/help_text.h"

#include "params/help_format.h"
#include "sph/param_table.h"
#include "sph/seed_documents.h"

namespace sph {

namespace {
using help_format::pad;
using help_format::shown;
using help_format::value_space;
}  // namespace

std::string params_help() {
  std::string out = "Run parameters (--set KEY=VALUE, or a scene file's \"params\"); a scene accepts a key only when\n"
                    "it runs the stage named after \"used by\" (`sph help SCENE` lists the keys of one scene):\n";
  const Params defaults;
  std::string_view group;
  for (const ParamInfo& info : param_table()) {
    if (info.group != group) {
      group = info.group;
      out += "\n" + std::string(group) + ".*\n";
    }
    out += "  " + pad(std::string(info.key), 24) + " " + value_space(info);
    if (!info.is_slot()) out += "; default " + shown(info.get(defaults));
    if (!info.alias.empty()) out += "; formerly " + std::string(info.alias);
    out += info.live ? "" : "; needs a reset";
    out += "\n      " + std::string(info.description);
    if (!info.stage.empty()) out += " (used by " + std::string(info.stage) + ")";
    out += "\n";
  }
  out += "\nScene values: scene.NAME, each scene its own (`sph help SCENE`).\n";
  return with_seed_citations(out);
}

std::string scenes_help() {
  std::string out = "Scenes (`sph help SCENE` explains one; `sph params` lists every run parameter):\n";
  for (const SceneSpec& s : scene_registry())
    out += "  " + pad(s.name, 26) + std::to_string(s.dim) + "D  " + s.category + "\n";
  return with_seed_citations(out);
}

}  // namespace sph

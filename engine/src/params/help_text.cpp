// `sph help SCENE`, `sph params`: text built from the scene table, the slot table and the parameter table.
#include "sph/help_text.h"

#include <charconv>
#include <cstdio>
#include <memory>

#include "text/number_text.h"
#include "core/pipeline.h"
#include "sph/param_table.h"

namespace sph {
namespace {

std::string pad(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A parameter's value as text: numbers in their shortest exact form (0.3, not 0.29999999999999999).
std::string shown(const std::string& value) {
  double v = 0.0;
  if (!parse_number(value, v)) return value;
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string unit_of(std::string_view unit) { return unit.empty() ? "dimensionless" : std::string(unit); }

/// "unit length/time, range [0, 10]" or "one of M4 M5 ..." for one run parameter.
std::string value_space(const ParamInfo& info) {
  if (!info.choices.empty()) {
    std::string s = "one of";
    for (const std::string& c : info.choices) s += " " + c;
    return s;
  }
  return unit_of(info.unit) + ", range [" + number(info.min) + ", " + number(info.max) + "]" +
         (info.integer ? ", integer" : "");
}

void add_param(std::string& out, const ParamInfo& info, const Params& now, const Params* defaults) {
  const std::string value = shown(info.get(now));
  out += "  " + pad(std::string(info.key), 24) + " = " + pad(value, 12) + "  " + value_space(info);
  if (defaults) out += ", default " + shown(info.get(*defaults));
  out += info.live ? "" : ", needs a reset";
  out += "\n      " + std::string(info.description) + "\n";
}

}  // namespace

std::string scene_help(const RunConfig& cfg) {
  const SceneSpec& s = *cfg.scene;
  std::string out = s.name + " (" + std::to_string(s.dim) + "D, " + s.category + ")\n  " + s.description + "\n";
  out += "  units: " + s.units.name + "; end time time.t_end = " + shown(exact_text(cfg.params.time.t_end)) + "\n\n";

  out += "Stages (physics.SLOT = option, [the options this scene accepts]):\n";
  for (const SlotInfo& slot : slot_table()) {
    const auto& allowed = s.allowed[static_cast<std::size_t>(slot.slot)];
    std::string accepts;
    for (const std::string& o : allowed.empty() ? slot.options : allowed) accepts += (accepts.empty() ? "" : " ") + o;
    if (allowed.empty() && slot.slot == Slot::Gravity) accepts = "none";
    out += "  " + pad("physics." + std::string(slot.key), 20) + " = " + pad(cfg.params.physics.get(slot.slot), 18) +
           " [" + accepts + "]\n      " + std::string(slot.description) + "\n";
  }
  std::string order;
  const Pipeline pipeline(cfg.params.physics, s.dim);
  for (const auto& st : pipeline.stages())
    order += (order.empty() ? "" : " -> ") + std::string(st->name());
  out += "  each step runs: " + (order.empty() ? std::string("(no stage)") : order) + "\n\n";

  out += "Parameters of these stages (--set KEY=VALUE; a file's \"params\"):\n";
  for (const ParamInfo& info : param_table())
    if (!info.is_slot() && info.is_active(cfg.params)) add_param(out, info, cfg.params, &s.defaults);

  if (!s.params.empty()) {
    out += "\nScene values (--set scene.NAME=VALUE; the particles are placed again):\n";
    for (const SceneParam& sp : s.params) {
      const auto it = cfg.values.find(sp.name);
      const double v = it == cfg.values.end() ? sp.value : it->second;
      out += "  " + pad("scene." + sp.name, 24) + " = " + pad(number(v), 12) + "  " + unit_of(sp.unit) + ", range [" +
             number(sp.min) + ", " + number(sp.max) + "]" + (sp.integer ? ", integer" : "") +
             ", default " + number(sp.value) + "\n      " + sp.description + "\n";
    }
  }

  out += "\nReference: ";
  std::unique_ptr<Reference> ref = s.reference ? s.reference(cfg.params, cfg.values) : nullptr;
  if (!ref) return out + "none (no exact or measured solution; errors.csv is not written)\n";
  out += ref->description() + "\n";
  std::string norms, measured;
  for (const RefColumn& c : ref->columns())
    (c.error ? norms : measured) += "    " + pad(c.name, 16) + c.description + "\n";
  if (!norms.empty()) out += "  error norms (errors.csv, smaller is better):\n" + norms;
  if (!measured.empty()) out += "  measured and exact values (errors.csv):\n" + measured;
  return out;
}

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
  return out;
}

std::string scenes_help() {
  std::string out = "Scenes (`sph help SCENE` explains one; `sph params` lists every run parameter):\n";
  for (const SceneSpec& s : scene_registry())
    out += "  " + pad(s.name, 26) + std::to_string(s.dim) + "D  " + s.category + "\n";
  return out;
}

}  // namespace sph

// `sph help SCENE` (sph/help_text.h): a scene as it runs with a configuration, its slots, the stages its
// pipeline runs, the parameters of those stages, its scene values and its reference.
#include <memory>

#include "core/pipeline.h"
#include "params/help_format.h"
#include "sph/help_text.h"
#include "sph/param_table.h"
#include "sph/seed_documents.h"
#include "text/number_text.h"

namespace sph {
namespace {

using help_format::number;
using help_format::pad;
using help_format::shown;
using help_format::unit_of;
using help_format::value_space;

/// One parameter line: key = value, what it may be, the scene's default, whether it needs a reset, meaning.
void add_param(std::string& out, const ParamInfo& info, const Params& now, const Params* defaults) {
  const std::string value = shown(info.get(now));
  out += "  " + pad(std::string(info.key), 24) + " = " + pad(value, 12) + "  " + value_space(info);
  if (defaults) out += ", default " + shown(info.get(*defaults));
  out += info.live ? "" : ", needs a reset";
  out += "\n      " + std::string(info.description) + "\n";
}

/// The help text of scene_help() without the seed documents it cites.
std::string scene_help_body(const RunConfig& cfg) {
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
  const Pipeline pipeline(cfg.params, s.dim);
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

  if (s.energy_bound > 0.0)
    out += "\nEnergy: E_tot stays within " + number(s.energy_bound) +
           " of |E_kin| + |E_int| + |E_pot| at the start (beyond, a warning, and exit 8 with gravity; far "
           "beyond, the run stops)\n";
  out += "\nReference: ";
  std::unique_ptr<Reference> ref = s.reference ? s.reference(cfg.params, cfg.values) : nullptr;
  if (!ref) return out + "none (no exact or measured solution; errors.csv is not written)\n";
  out += ref->description() + "\n";
  std::string norms, measured;
  for (const RefColumn& c : ref->columns())
    (c.error ? norms : measured) += "    " + pad(c.name, 16) + c.description + "\n";
  if (!norms.empty()) out += "  error norms (errors.csv, smaller is better):\n" + norms;
  if (!measured.empty()) out += "  measured and exact values (errors.csv):\n" + measured;
  if (!s.error_bounds.empty()) {
    out += "  bounds a correct run keeps (measured at the defaults, with margin; beyond one, a warning):\n";
    for (const ErrorBound& b : s.error_bounds)
      out += "    " + pad(b.column, 16) + "<= " + number(b.max) + (b.from > 0.0 ? " from t = " + number(b.from) : "") + "\n";
  }
  if (!s.assumptions.empty()) {
    out += "  assumes (outside, a warning at the start):\n";
    for (const RefAssumption& a : s.assumptions)
      out += "    " + a.key + " " + range_text(a) + ": " + a.why + "\n";
  }
  return out;
}

}  // namespace

std::string scene_help(const RunConfig& cfg) { return with_seed_citations(scene_help_body(cfg)); }

}  // namespace sph

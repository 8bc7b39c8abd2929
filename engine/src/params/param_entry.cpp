// The parts of a parameter-table entry that are not templates (params/param_entry.h).
#include "params/param_entry.h"

#include "sph/suggest.h"

namespace sph::param_entry {

ParamInfo base(const Common& c) {
  ParamInfo p;
  p.key = c.key;
  p.group = c.key.substr(0, c.key.find('.'));
  p.unit = c.unit;
  p.description = c.what;
  p.live = c.live;
  p.alias = c.alias;
  p.stage = c.owner.stage;
  p.slot = c.owner.slot;
  p.active = c.owner.active;
  return p;
}

std::string not_one_of(std::string_view key, const std::string& text, const std::vector<std::string>& names) {
  std::string err = std::string(key) + " = '" + text + "' is not one of:";
  for (const auto& n : names) err += " " + n;
  return err + did_you_mean(text, names);
}

ParamInfo slot(const SlotInfo& s, std::string_view key, std::string_view alias) {
  ParamInfo p = base({key, "choice", s.description, alias, {}, s.live});
  p.choices = s.options;
  p.slot = s.slot;
  const Slot which = s.slot;
  p.get = [which](const Params& prm) { return prm.physics.get(which); };
  p.set = [which, key, names = p.choices](Params& prm, const std::string& text, std::string& err) {
    if (prm.physics.set(which, text)) return true;
    err = not_one_of(key, text, names);
    return false;
  };
  return p;
}

}  // namespace sph::param_entry

// Every run parameter declared once: key GROUP.NAME, unit, range, meaning, whether it is safe to change
// while a scene runs, and the stage that uses it. The table drives the JSON scene keys, the --set
// overrides and the GUI widgets; a parameter whose stage the scene does not run is not shown and,
// when set explicitly, refused (RunConfig::validate).
#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sph/params.h"

namespace sph {

struct ParamInfo {
  std::string_view key;          ///< JSON key and --set name, GROUP.NAME (physics.SLOT for the slots)
  std::string_view group;        ///< GROUP: kernel, h, time, gas, liquid, visc, ... and physics
  std::string_view unit;         ///< unit ("dimensionless" when there is none)
  std::string_view description;  ///< one line, with the seed equation it enters
  double min = 0.0, max = 0.0;   ///< allowed range for numbers (inclusive)
  bool live = true;              ///< true: takes effect at the next step; false: needs a reset
  bool integer = false;          ///< a whole number
  std::vector<std::string> choices;  ///< names, for enumerations
  std::string_view alias;        ///< the flat key of earlier versions (e.g. "alpha"), still accepted
  std::string_view stage;        ///< the stage that uses it, for messages ("" = every scene)
  Slot slot = Slot::Count;       ///< the slot itself (physics.*), or the one whose choice runs that stage
  std::function<bool(const Params&)> active;                    ///< used by the chosen physics (null = always)
  std::function<std::string(const Params&)> get;                ///< value as text
  std::function<bool(Params&, const std::string&, std::string&)> set;  ///< parse + range check
  bool is_active(const Params& p) const { return !active || active(p); }
  bool is_slot() const { return group == "physics"; }
};

const std::vector<ParamInfo>& param_table();
/// By key or by its old flat alias.
const ParamInfo* find_param(std::string_view key);

/// Parses a whole string as a finite double; false on trailing junk, empty or non-finite input.
bool parse_number(const std::string& s, double& out);

}  // namespace sph

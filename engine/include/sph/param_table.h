// Every run parameter declared once: key, unit, range, meaning and whether it is safe to change while
// a scene runs. The table drives the JSON scene keys, the --set overrides and the GUI widgets.
#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sph/params.h"

namespace sph {

struct ParamInfo {
  std::string_view key;          ///< JSON key and --set name
  std::string_view unit;         ///< unit, or "-" for dimensionless
  std::string_view description;  ///< one line, with the seed equation it enters
  double min = 0.0, max = 0.0;   ///< allowed range for numbers (inclusive)
  bool live = true;              ///< true: takes effect at the next step; false: needs a reset
  std::vector<std::string> choices;                             ///< names, for enumerations
  std::function<std::string(const Params&)> get;                ///< value as text
  std::function<bool(Params&, const std::string&, std::string&)> set;  ///< parse + range check
};

const std::vector<ParamInfo>& param_table();
const ParamInfo* find_param(std::string_view key);

/// Parses a whole string as a finite double; false on trailing junk, empty or non-finite input.
bool parse_number(const std::string& s, double& out);

}  // namespace sph

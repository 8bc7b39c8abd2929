// Widgets for run parameters, built from their one declaration in sph::param_table(): a combo for
// enumerations, a slider for short linear ranges, a text field otherwise. Every widget's tooltip gives
// the description (with the seed equation), unit, range, and whether it is live or needs a reset.
#pragma once
#include <string>
#include <vector>

#include "sph/param_table.h"

namespace sph::gui {

/// Tooltip for the last item: the parameter's description, unit, range and live/needs-reset.
void param_tooltip(const ParamInfo& info);

/// What a slider shows at 0 for a parameter whose description ends "0 = MEANING": "0 (MEANING)", e.g.
/// kernel.eta's "0 (the kernel's default)" rather than a bare 0; "" when 0 means nothing special.
std::string zero_text(const ParamInfo& info);

/// One widget; true when a new value was written to p (through info.set, so range-checked). A value
/// the table rejects leaves p unchanged and puts the reason in *err. `pending` marks a value that
/// differs from what the engine runs with (needs reset).
/// For a choice, `allowed` (if not empty) restricts the options offered (a scene's slot options).
bool param_widget(const ParamInfo& info, Params& p, bool pending, std::string* err,
                  const std::vector<std::string>& allowed = {});

}  // namespace sph::gui

// The compare panel's field: run B's overrides typed as "kernel.type=M6, visc.alpha=0".
#pragma once
#include <string>
#include <vector>

namespace sph::gui {

/// Splits at commas (and newlines), trims spaces, drops empty items: {"kernel.type=M6", "visc.alpha=0"}.
std::vector<std::string> split_overrides(const std::string& text);

}  // namespace sph::gui

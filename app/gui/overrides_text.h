// The compare panel's field: run B's overrides typed as "kernel.type=M6, visc.alpha=0"; a sweep typed as
// "kernel.eta=1.0,1.5" (--sweep) or as a key and "1.0, 1.5" (the sweep panel).
#pragma once
#include <string>
#include <vector>

namespace sph::gui {

/// Splits at commas (and newlines), trims spaces, drops empty items: {"kernel.type=M6", "visc.alpha=0"}.
std::vector<std::string> split_overrides(const std::string& text);

/// A sweep's values: split at commas, semicolons, spaces and newlines, empty items dropped.
std::vector<std::string> split_values(const std::string& text);

/// "KEY=V1,V2,...": false (with *err saying what is wrong) without a key, an '=' or a value.
bool split_sweep(const std::string& text, std::string* key, std::vector<std::string>* values, std::string* err);

}  // namespace sph::gui

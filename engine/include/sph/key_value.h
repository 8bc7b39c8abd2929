// "key=value" overrides (sph --set and --compare-set, sph-gui --set, a comparison's run B): one split,
// at the first '=' with a key before it, and one way to apply it to a RunConfig.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "sph/config.h"

namespace sph {

struct KeyValue {
  std::string key, value;
};

/// text split at its first '=' (the value may hold more); nullopt without one or with nothing before it.
std::optional<KeyValue> split_key_value(std::string_view text);

/// cfg.set(key, value, "FLAG TEXT") for TEXT = "key=value"; throws ConfigError "FLAG TEXT: expected
/// key=value" when TEXT is not one (and whatever set() throws).
void apply_key_value(RunConfig& cfg, const std::string& flag, const std::string& text);

}  // namespace sph

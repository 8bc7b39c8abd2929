// The one "key=value" split of the overrides (sph/key_value.h).
#include "sph/key_value.h"

namespace sph {

std::optional<KeyValue> split_key_value(std::string_view text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0) return std::nullopt;
  return KeyValue{std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

void apply_key_value(RunConfig& cfg, const std::string& flag, const std::string& text) {
  const std::string source = flag + " " + text;
  const std::optional<KeyValue> kv = split_key_value(text);
  if (!kv) throw ConfigError(source + ": expected key=value");
  cfg.set(kv->key, kv->value, source);
}

}  // namespace sph

#include "sph/compare.h"

#include <cstdio>

#include "sph/kernel.h"
#include "sph/key_value.h"
#include "sph/param_table.h"
#include "text/number_text.h"

namespace sph {
namespace {

std::string key_of(const std::string& kv) { return kv.substr(0, kv.find('=')); }

/// The value of key in cfg as text ("" if there is no such key).
std::string value_of(const RunConfig& cfg, const std::string& key) {
  if (key.rfind("scene.", 0) == 0) {
    const auto it = cfg.values.find(key.substr(6));
    return it == cfg.values.end() ? std::string() : short_text(it->second);
  }
  const ParamInfo* info = find_param(key);
  if (info == nullptr) return {};
  const std::string text = info->get(cfg.params);
  double v = 0.0;
  if (!parse_number(text, v)) return text;  // a choice: M6, leapfrog, standard
  char buf[48];
  if (key == "kernel.eta" && v == 0.0 && cfg.scene)  // 0 = the kernel's default: say which
    std::snprintf(buf, sizeof buf, "%.6g (default)", Kernel(cfg.params.kernel.type, cfg.scene->dim).default_eta());
  else
    std::snprintf(buf, sizeof buf, "%.6g", v);  // a label, not a value to read back
  return buf;
}

}  // namespace

RunConfig fork_config(const RunConfig& a, const std::vector<std::string>& overrides) {
  RunConfig b = a;
  for (const std::string& kv : overrides) {
    const std::optional<KeyValue> split = split_key_value(kv);
    if (!split) throw ConfigError("compare: '" + kv + "': expected key=value");
    b.set(split->key, split->value, "compare " + kv);
  }
  b.validate();
  return b;
}

std::string compare_label(const RunConfig& cfg, const std::vector<std::string>& overrides) {
  std::string out;
  for (const std::string& kv : overrides) {
    const std::string key = key_of(kv), value = value_of(cfg, key);
    if (value.empty()) continue;
    out += (out.empty() ? "" : ", ") + key + "=" + value;
  }
  return out;
}

std::vector<std::string> differences(const RunConfig& a, const RunConfig& b) {
  std::vector<std::string> out;
  for (const ParamInfo& info : param_table()) {
    const std::string vb = info.get(b.params);
    if (info.get(a.params) != vb) out.push_back(std::string(info.key) + "=" + vb);
  }
  for (const auto& [name, v] : b.values) {
    const auto it = a.values.find(name);
    if (it == a.values.end() || it->second != v) out.push_back("scene." + name + "=" + short_text(v));
  }
  return out;
}

}  // namespace sph

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

std::vector<std::string> sweep_values(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (const char c : text + ",") {
    if (c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\n') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  return out;
}

bool split_sweep(const std::string& text, std::string* key, std::vector<std::string>* values, std::string* err) {
  const auto eq = text.find('=');
  *key = eq == std::string::npos ? std::string() : text.substr(0, eq);
  *values = eq == std::string::npos ? std::vector<std::string>{} : sweep_values(text.substr(eq + 1));
  if (key->empty() || values->empty()) {
    *err = "'" + text + "' is not KEY=V1,V2,... (e.g. kernel.eta=1.0,1.5)";
    return false;
  }
  if (values->size() > kMaxSweepRuns) {
    *err = std::to_string(values->size()) + " values of " + *key + ", at most " + std::to_string(kMaxSweepRuns);
    return false;
  }
  return true;
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

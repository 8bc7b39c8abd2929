#include "cli_compare.h"

#include <cstdio>

#include "sph/compare.h"
#include "sph/key_value.h"
#include "summary_item.h"

namespace sph::cli {

std::optional<CompareSetup> resolve_compare(const CompareOptions& opt, const RunConfig& a, double until) {
  if (opt.scene.empty() && opt.sets.empty()) return std::nullopt;
  CompareSetup c;
  try {
    c.b = opt.scene.empty() ? a : RunConfig::load(opt.scene);
  } catch (const ConfigError& e) {
    throw ConfigError(std::string("--compare ") + opt.scene + ": " + e.what());
  }
  if (c.b.scene->name != a.scene->name)
    throw ConfigError("--compare " + opt.scene + ": run B is scene " + c.b.scene->name + ", run A scene " +
                      a.scene->name + "; both runs must be the same scene (with other parameters)");
  for (const std::string& kv : opt.sets) apply_key_value(c.b, "--compare-set", kv);
  if (until >= 0.0) c.b.params.time.t_end = until;
  c.b.validate();
  for (const std::string& d : differences(a, c.b))  // the end and output times say nothing about the runs
    if (d.rfind("time.t_end=", 0) != 0 && d.rfind("time.dt_out=", 0) != 0) c.differences.push_back(d);
  const std::string la = compare_label(a, c.differences), lb = compare_label(c.b, c.differences);
  c.label_a = la.empty() ? "A" : "A: " + la;
  c.label_b = lb.empty() ? "B (same parameters)" : "B: " + lb;
  return c;
}

std::vector<std::pair<std::string, double>> reference_errors(const World& w) {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<double> v = w.report().reference_values();
  for (std::size_t k = 0; k < w.report().reference_columns().size() && k < v.size(); ++k)
    out.emplace_back(w.report().reference_columns()[k].name, v[k]);
  return out;
}

std::string compare_summary(const World& b, const CompareSetup& setup) {
  char head[160];
  std::snprintf(head, sizeof head, "run %s: t = %g after %lld steps, %zu particles", setup.label_b.c_str(), b.time(),
                static_cast<long long>(b.steps()), b.particles().size());
  std::string line = head;
  for (const auto& [name, v] : reference_errors(b)) line += summary_item(name, v);
  return line;
}

}  // namespace sph::cli

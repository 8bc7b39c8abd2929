// The reference guard of RunChecks: whether a run's comparison with its scene's reference still means
// what it says. At the start (and after new parameters) the values the reference assumes are checked
// against their ranges (SceneSpec::assumptions); at each output its error norms are checked against the
// scene's bounds (SceneSpec::error_bounds); after each step, whether the run has passed the time the
// reference applies to. All warn: the run goes on and errors.csv keeps every value.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "sph/compare.h"
#include "sph/param_table.h"
#include "sph/run_checks.h"
#include "sph/scene.h"

namespace sph {
namespace {

/// The value of a scene value "scene.NAME" (from `values`: the scene's defaults with the run's values over
/// them) or of a numeric parameter key; NaN for a key that is neither.
double value_of(const RunConfig& cfg, const SceneValues& values, const std::string& key) {
  constexpr std::string_view prefix = "scene.";
  if (key.starts_with(prefix)) {
    const auto it = values.find(key.substr(prefix.size()));
    return it == values.end() ? std::nan("") : it->second;
  }
  const ParamInfo* info = find_param(key);
  double v = std::nan("");
  if (!info || !info->get || !parse_number(info->get(cfg.params), v)) return std::nan("");
  return v;
}

/// Where this run's values differ from the scene's defaults, at which its bounds were measured, as
/// "; this run differs from them in KEY=VALUE, ... (and N more)" ("" at the defaults): a warning on a
/// variant (elliptical_drop_standard.json) or after a --set says which choice it comes with. The end
/// and the output interval are left out: they move no error, and a run resumed with another --until
/// must write the warning of the run that never stopped.
std::string changed_from_defaults(const RunConfig& cfg) {
  std::vector<std::string> diff;
  try {
    diff = differences(RunConfig::from_scene(cfg.scene->name), cfg);
  } catch (const std::exception&) {
    return "";  // a scene without registered defaults
  }
  std::erase_if(diff, [](const std::string& d) {
    return d.starts_with("time.t_end=") || d.starts_with("time.dt_out=");
  });
  constexpr std::size_t kShown = 4;
  std::string out;
  for (std::size_t i = 0; i < diff.size() && i < kShown; ++i)
    out += (i == 0 ? "; this run differs from them in " : ", ") + diff[i];
  if (diff.size() > kShown) out += " and " + std::to_string(diff.size() - kShown) + " more";
  return out;
}

}  // namespace

std::string range_text(const RefAssumption& a) {
  char s[80];
  if (a.lo == a.hi) std::snprintf(s, sizeof s, "= %g", a.lo);
  else if (a.hi >= 1e300) std::snprintf(s, sizeof s, ">= %g", a.lo);
  else std::snprintf(s, sizeof s, "in [%g, %g]", a.lo, a.hi);
  return s;
}

void RunChecks::check_assumptions(const RunConfig& cfg) {
  std::string what;
  SceneValues values = cfg.scene->default_values();
  for (const auto& [k, v] : cfg.values) values[k] = v;
  for (const RefAssumption& a : cfg.scene->assumptions) {
    const double v = a.value ? a.value(cfg.params, values) : value_of(cfg, values, a.key);
    if (v >= a.lo && v <= a.hi) continue;
    char line[400];
    std::snprintf(line, sizeof line, "%s = %.4g, where the reference assumes %s %s: %s", a.key.c_str(), v,
                  a.key.c_str(), range_text(a).c_str(), a.why.c_str());
    what += (what.empty() ? "" : "; ") + std::string(line);
  }
  if (what.empty()) return;
  what += " (errors.csv compares with it all the same; its error bounds are not claimed)";
  warn("assumption", -1, what, 0, 0.0, true);
}

void RunChecks::check_error_bounds(const RunConfig& cfg, const Reference* ref, const std::vector<RefColumn>& columns,
                                   const std::vector<double>& values, std::int64_t step, double t) {
  if (!ref || !(t <= ref->valid_until() * (1.0 + 1e-12))) return;
  for (const ErrorBound& b : cfg.scene->error_bounds) {
    if (t < b.from) continue;
    const int k = find_column(columns, b.column);
    if (k < 0 || static_cast<std::size_t>(k) >= values.size()) continue;
    const double v = values[static_cast<std::size_t>(k)];
    if (!(v > b.max)) continue;  // NaN: not measured yet (e.g. a star state before the waves form)
    char head[200];
    std::snprintf(head, sizeof head,
                  "%s = %.3g at t = %.4g, beyond this scene's bound %.3g for it (measured at its defaults, with margin",
                  b.column.c_str(), v, t, b.max);
    warn("accuracy:" + b.column, -1,
         head + changed_from_defaults(cfg) +
             "): the result is less accurate than the scene's reference claims (errors.csv has every value)",
         step, t);
  }
}

void RunChecks::check_reference(const Reference* ref, std::int64_t step, double t) {
  if (!ref) return;
  const double until = ref->valid_until();
  if (!(t > until * (1.0 + 1e-12))) return;
  char what[320];
  std::snprintf(what, sizeof what,
                "from t = %.4g %s: the reference no longer applies (errors.csv marks those rows valid = 0)", until,
                ref->valid_until_reason().c_str());
  warn("reference", -1, what, step, t);
}

}  // namespace sph

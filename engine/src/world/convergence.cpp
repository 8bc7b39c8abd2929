#include "sph/convergence.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sph/world.h"
#include "text/number_text.h"

namespace sph {
namespace {

std::string format(double v) { return exact_text(v); }  // for RunConfig::set
std::string text(double v) { return short_text(v); }     // for the CSV

}  // namespace

ConvergenceStudy resolve_study(const RunConfig& base, const ConvergenceStudy& asked) {
  if (base.scene == nullptr) throw ConfigError("no scene given");
  const SceneSpec& sc = *base.scene;
  if (!sc.reference) throw ConfigError("scene " + sc.name + " has no reference: there is no error to converge");
  ConvergenceStudy s = asked;
  const ConvergenceDefaults& d = sc.convergence;
  if (s.key.empty()) s.key = d.key;
  if (s.key.empty()) {
    for (const SceneParam& p : sc.params)
      if (p.name == "n") s.key = "scene.n";
  }
  if (s.key.empty()) throw ConfigError("scene " + sc.name + " has no default convergence key: give --key");
  if (s.values.empty() && s.key == d.key) s.values = d.values;
  if (s.values.empty() && s.key == "scene.n") s.values = {60, 120, 240, 480, 960, 1920};
  if (s.values.size() < 2) throw ConfigError("a convergence study needs at least two values (--values)");
  if (s.t < 0.0) s.t = d.t >= 0.0 ? d.t : base.params.time.t_end;
  if (!(s.t > 0.0) || !std::isfinite(s.t)) throw ConfigError("the comparison time must be > 0");
  // the column: checked against a World of the first value (the reference's columns may depend on it)
  RunConfig probe = base;
  probe.set(s.key, format(s.values.front()), "--key " + s.key);
  World w(probe);
  const auto& cols = w.report().reference_columns();
  if (s.column.empty() && s.key == d.key) s.column = d.column;
  if (s.column.empty()) {
    const int k = w.report().reference()->primary();
    s.column = cols.at(static_cast<std::size_t>(k)).name;
  } else if (find_column(cols, s.column) < 0) {
    std::string known;
    for (const auto& c : cols) known += " " + c.name;
    throw ConfigError("--column " + s.column + ": scene " + sc.name + " has no such reference column (columns:" + known +
                      ")");
  }
  return s;
}

ConvergenceResult run_convergence(const RunConfig& base, const ConvergenceStudy& study,
                                  const std::function<void(const ConvergenceRun&)>& progress) {
  ConvergenceResult r;
  r.scene = base.scene->name;
  r.key = study.key;
  r.column = study.column;
  r.t = study.t;
  for (double value : study.values) {
    RunConfig cfg = base;
    cfg.set(study.key, format(value), "--key " + study.key);
    cfg.params.time.t_end = study.t;
    cfg.validate();
    const auto t0 = std::chrono::steady_clock::now();
    World w(cfg);
    while (w.time() < study.t) w.step(study.t - w.time());
    ConvergenceRun run;
    run.value = value;
    run.h = study.key == "time.dt" ? value : w.report().spacing();  // a timestep study converges in dt
    run.error = w.report().reference_value(study.column);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.steps = w.steps();
    run.particles = w.particles().fluid();
    run.valid = study.t <= w.report().reference()->valid_until() * (1.0 + 1e-12);
    run.warnings = w.checks().warnings().size();
    run.order = std::numeric_limits<double>::quiet_NaN();
    if (!r.runs.empty()) {
      const ConvergenceRun& prev = r.runs.back();
      run.order = std::log(prev.error / run.error) / std::log(prev.h / run.h);
    }
    if (r.column_description.empty())
      for (const RefColumn& c : w.report().reference_columns())
        if (c.name == study.column) r.column_description = c.description;
    r.runs.push_back(run);
    if (progress) progress(run);
  }
  // least squares of log e on log h
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (const ConvergenceRun& run : r.runs) {
    if (!(run.error > 0.0) || !(run.h > 0.0)) continue;
    const double x = std::log(run.h), y = std::log(run.error);
    sx += x; sy += y; sxx += x * x; sxy += x * y; m += 1.0;
  }
  r.slope = m >= 2.0 ? (m * sxy - sx * sy) / (m * sxx - sx * sx) : std::numeric_limits<double>::quiet_NaN();
  return r;
}

std::string convergence_csv(const ConvergenceResult& r, bool comment) {
  std::string s;
  if (comment)
    s = "# " + r.scene + ": " + r.column + " (" + r.column_description + ") at t = " + text(r.t) + " against " + r.key +
        "; " + r.step_name() + " = " + r.step_meaning() + ", order = log(e1/e2)/log(" + r.step_name() + "1/" +
        r.step_name() + "2); fitted slope " + text(r.slope) + "\n";
  s += "value," + r.step_name() + ",error,order,wall_s,steps\n";
  for (const ConvergenceRun& run : r.runs)
    s += text(run.value) + "," + text(run.h) + "," + text(run.error) + "," +
         (std::isnan(run.order) ? std::string() : text(run.order)) + "," + text(run.wall_s) + "," +
         std::to_string(run.steps) + "\n";
  return s;
}

std::string convergence_markdown(const ConvergenceResult& r) {
  char buf[256];
  std::string s = "Convergence of `" + r.scene + "`: " + r.column + " at t = " + format(r.t) + " (" +
                  r.column_description + ")\n\n";
  s += "| " + r.key + " | " + r.step_name() + " | " + r.column +
       " | order | wall [s] | steps |\n|---:|---:|---:|---:|---:|---:|\n";
  for (const ConvergenceRun& run : r.runs) {
    char order[32] = "-";
    if (!std::isnan(run.order)) std::snprintf(order, sizeof order, "%.3f", run.order);
    std::snprintf(buf, sizeof buf, "| %g | %.4g | %.4g | %s | %.3f | %lld |\n", run.value, run.h, run.error, order,
                  run.wall_s, static_cast<long long>(run.steps));
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "\nLeast-squares slope of log e against log %s: %.3f\n", r.step_name().c_str(),
                r.slope);
  s += buf;
  return s;
}

}  // namespace sph

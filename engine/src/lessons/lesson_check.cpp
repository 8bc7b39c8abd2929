// Lesson claims evaluated headless (sph/lesson_check.h): each run steps a World as `sph converge` does,
// samples the metric after every step and reduces it; the claim compares the reduced numbers.
#include "sph/lesson_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "lesson_metric.h"
#include "lesson_sets_text.h"
#include "sph/world.h"
#include "text/number_text.h"

namespace sph {
namespace {

/// |E_tot - E0| / scale: the relative energy error of the run [dimensionless].
struct EnergyDrift {
  double e0 = 0.0, scale = 1.0;
  explicit EnergyDrift(const World& w) {
    const Diagnostics d = w.report().diagnostics();
    e0 = d.E_tot;
    scale = std::abs(d.E_kin) + std::abs(d.E_int) + std::abs(d.E_pot);
    if (!(scale > 0.0)) scale = 1.0;
  }
  double operator()(const World& w) const { return std::abs(w.report().diagnostics().E_tot - e0) / scale; }
};

/// Total variation of v_x along x over the fluid particles [velocity]: sum |v_x(k+1) - v_x(k)| in x order.
/// The exact Sod profile has 2 x 0.927; oscillations behind a shock add to it.
double total_variation_vx(const World& w) {
  const Particles& p = w.particles();
  std::vector<std::size_t> order(p.fluid());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return p.x[0][i] < p.x[0][j] || (p.x[0][i] == p.x[0][j] && i < j);
  });
  double tv = 0.0;
  for (std::size_t k = 1; k < order.size(); ++k) tv += std::abs(p.v[0][order[k]] - p.v[0][order[k - 1]]);
  return tv;
}

std::string num(double v) { return g_text(v, 4); }

std::string sets_label(const LessonSets& sets) { return lessons::join_sets(sets, ",", "defaults"); }

}  // namespace

namespace lessons {

std::string metric_names(const RunConfig& cfg, const std::string& metric, bool* known) {
  World w(cfg);
  std::string names;
  *known = false;
  for (const RefColumn& c : w.report().reference_columns()) {
    names += " " + c.name;
    *known = *known || c.name == metric;
  }
  for (const std::string& m : extra_metrics()) {
    names += " " + m;
    *known = *known || m == metric;
  }
  if (metric == "tv_vx" && w.config().scene->dim != 1) *known = false;  // a profile along x: 1D scenes only
  return names;
}

}  // namespace lessons

std::vector<std::string> extra_metrics() { return {"E_drift", "tv_vx", "updates", "v_max"}; }

RunConfig lesson_config(const LessonStep& step, const LessonSets& extra) {
  RunConfig cfg = RunConfig::load(step.scene);
  for (const auto& [k, v] : step.sets) cfg.set(k, v, "set " + k);
  for (const auto& [k, v] : extra) cfg.set(k, v, "check " + k);
  cfg.validate();
  return cfg;
}

double measure(const RunConfig& base, const std::string& metric, const std::string& reduce, double until) {
  RunConfig cfg = base;
  const double t_end = until > 0.0 ? until : cfg.params.time.t_end;
  cfg.params.time.t_end = t_end;
  World w(cfg);
  bool known = false;
  for (const RefColumn& c : w.report().reference_columns()) known = known || c.name == metric;
  const std::vector<std::string> extras = extra_metrics();
  const bool extra = std::find(extras.begin(), extras.end(), metric) != extras.end();
  if (!known && !extra) throw LessonError("scene " + cfg.scene->name + " has no metric '" + metric + "'");
  w.evaluate();
  const EnergyDrift drift(w);
  const auto value = [&] {
    if (metric == "E_drift") return drift(w);
    if (metric == "tv_vx") return total_variation_vx(w);
    if (metric == "updates") return static_cast<double>(w.report().diagnostics().updates);  // particle evaluations
    if (metric == "v_max") return w.report().diagnostics().v_max;  // the largest fluid speed
    return w.report().reference_value(metric);
  };
  double first = 0.0, second = 0.0, largest = 0.0;  // max |value| over the halves and the run
  while (w.time() < t_end) {
    w.step(t_end - w.time());
    if (reduce == "end") continue;
    const double v = std::abs(value());
    largest = std::max(largest, v);
    double& half = w.time() <= 0.5 * t_end ? first : second;
    half = std::max(half, v);
  }
  if (reduce == "max") return largest;
  if (reduce == "growth") return first > 0.0 ? second / first : (second > 0.0 ? std::numeric_limits<double>::infinity() : 1.0);
  return value();
}

CheckResult evaluate_check(const LessonStep& step) {
  const LessonCheck& k = step.check;
  const std::string m = metric_label(k);
  CheckResult r;
  const auto run = [&](const LessonSets& extra) {
    const double v = measure(lesson_config(step, extra), k.metric, k.reduce, k.until);
    r.measured.push_back(v);
    return v;
  };
  const std::string by = k.factor > 1.0 ? " / " + num(k.factor) : "";
  switch (k.type) {
    case LessonCheck::Type::Falls: {
      r.pass = true;
      for (double value : k.values) run({{k.key, exact_text(value)}});
      for (std::size_t i = 1; i < k.values.size(); ++i) {
        const double lo = r.measured[i], hi = r.measured[i - 1];
        const bool ok = lo * k.factor < hi;
        r.pass = r.pass && ok;
        if (!r.text.empty()) r.text += "; ";
        r.text += m + "(" + k.key + "=" + num(k.values[i]) + ")=" + num(lo) + (ok ? " < " : " >= ") + m + "(" + k.key +
                  "=" + num(k.values[i - 1]) + ")=" + num(hi) + by + " (ratio " + num(hi / lo) + ")";
      }
      break;
    }
    case LessonCheck::Type::Compare: {
      const double a = run(k.a), b = run(k.b);
      const double lo = k.smaller == 'a' ? a : b, hi = k.smaller == 'a' ? b : a;
      const LessonSets& lo_sets = k.smaller == 'a' ? k.a : k.b;
      const LessonSets& hi_sets = k.smaller == 'a' ? k.b : k.a;
      r.pass = lo * k.factor < hi;
      r.text = m + "[" + sets_label(lo_sets) + "]=" + num(lo) + (r.pass ? " < " : " >= ") + m + "[" +
               sets_label(hi_sets) + "]=" + num(hi) + by + " (ratio " + num(hi / lo) + ")";
      break;
    }
    case LessonCheck::Type::Below:
    case LessonCheck::Type::Above: {
      const double v = run({});
      const bool below = k.type == LessonCheck::Type::Below;
      r.pass = below ? v < k.limit : v > k.limit;
      r.text = m + "=" + num(v) + (r.pass == below ? " < " : " > ") + num(k.limit);
      if (!r.pass && v == k.limit) r.text = m + "=" + num(v) + " = " + num(k.limit);
      break;
    }
  }
  return r;
}

}  // namespace sph

#include "cli_sweep.h"

#include <cstdio>

#include "cli_compare.h"
#include "run_report.h"
#include "sph/compare.h"
#include "summary_item.h"

namespace sph::cli {

std::unique_ptr<SweepRuns> SweepRuns::resolve(const std::string& text, const RunConfig& a, double until) {
  if (text.empty()) return nullptr;
  auto s = std::make_unique<SweepRuns>();
  std::vector<std::string> values;
  std::string err;
  if (!split_sweep(text, &s->key_, &values, &err)) throw ConfigError("--sweep: " + err);  // usage_error checked
  for (const std::string& v : values) {
    RunConfig c;
    try {
      c = fork_config(a, {s->key_ + "=" + v});
    } catch (const ConfigError& e) {
      throw ConfigError(std::string("--sweep: ") + e.what());
    }
    if (until >= 0.0) c.params.time.t_end = until;
    s->labels_.push_back(compare_label(c, {s->key_ + "=" + v}));
    s->configs_.push_back(std::move(c));
  }
  return s;
}

std::string SweepRuns::usage_error(const std::string& text, bool comparing) {
  if (text.empty()) return "";
  std::string key, err;
  std::vector<std::string> values;
  if (!split_sweep(text, &key, &values, &err)) return err;
  if (comparing) return "not with --compare (a sweep of one value is an A/B run)";
  return "";
}

void SweepRuns::build() {
  for (const RunConfig& c : configs_) worlds_.push_back(std::make_unique<World>(c));
}

void SweepRuns::advance_to(double t, const World*& current) {
  const World* a = current;
  for (std::size_t k = 0; k < worlds_.size(); ++k) {
    current = worlds_[k].get();
    try {
      worlds_[k]->advance_to(t);
    } catch (const DivergedError&) {
      std::fprintf(stderr, "sph: sweep run %s diverged:\n", labels_[k].c_str());
      throw;
    }
  }
  current = a;
}

void SweepRuns::check_output(const World*& current) {
  const World* a = current;
  for (const auto& w : worlds_) {
    current = w.get();
    w->check_output();
  }
  current = a;
}

void SweepRuns::print_summary() const {
  for (std::size_t k = 0; k < worlds_.size(); ++k) {
    const World& w = *worlds_[k];
    char head[160];
    std::snprintf(head, sizeof head, "sweep run %s: t = %g after %lld steps", labels_[k].c_str(), w.time(),
                  static_cast<long long>(w.steps()));
    std::string line = head;
    for (const auto& [name, v] : reference_errors(w)) line += summary_item(name, v);
    std::printf("%s\n", line.c_str());
  }
}

void SweepRuns::print_warnings() const {
  for (const auto& w : worlds_) cli::print_warnings(*w);
}

bool SweepRuns::energy_beyond_bound() const {
  for (const auto& w : worlds_)
    if (w->checks().energy_beyond_bound(w->config())) return true;
  return false;
}

}  // namespace sph::cli

#include "sph/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

namespace sph {
namespace {

/// The scene's count parameter that dominates (largest estimated particle number) and its estimate.
double count_of(const RunConfig& cfg, std::string* key) {
  double best = 0.0;
  if (!cfg.scene) return 0.0;
  for (const SceneParam& p : cfg.scene->params) {
    if (p.unit != "count") continue;
    const auto it = cfg.values.find(p.name);
    const double v = it != cfg.values.end() ? it->second : p.value;
    double n = v;
    if (p.name.find("n_side") != std::string::npos) n = 1.2 * std::pow(v, cfg.scene->dim);
    else if (p.description.find("per ") != std::string::npos) n = 2.0 * v;
    if (n > best) {
      best = n;
      if (key) *key = "scene." + p.name;
    }
  }
  return best;
}

}  // namespace

double estimated_particles(const RunConfig& cfg) { return count_of(cfg, nullptr); }

double run_memory_bytes(double particles, int dim) { return particles * (dim == 3 ? 2560.0 : 1024.0); }

double available_memory_bytes() {
  double avail = std::numeric_limits<double>::infinity();
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    unsigned long long kb = 0;
    if (std::sscanf(line.c_str(), "MemAvailable: %llu kB", &kb) == 1) avail = 1024.0 * static_cast<double>(kb);
  }
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY) {
    double mapped = 0.0;  // /proc/self/statm: the first number is the mapped size in pages
    std::ifstream statm("/proc/self/statm");
    unsigned long long pages = 0;
    if (statm >> pages) mapped = static_cast<double>(pages) * static_cast<double>(::sysconf(_SC_PAGESIZE));
    avail = std::min(avail, std::max(0.0, static_cast<double>(lim.rlim_cur) - mapped));
  }
  return avail;
}

std::string memory_text(double bytes) {
  char buf[48];
  if (bytes >= 1024.0 * 1024.0 * 1024.0) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  else std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1024.0 * 1024.0));
  return buf;
}

void check_run_memory(const RunConfig& cfg) {
  std::string key;
  const double n = count_of(cfg, &key);
  if (n <= 0.0 || !cfg.scene) return;
  const double need = run_memory_bytes(n, cfg.scene->dim), avail = available_memory_bytes();
  if (need <= avail) return;
  char count[32];
  std::snprintf(count, sizeof count, "%.3g", n);
  throw ConfigError(key + ": about " + std::string(count) + " particles would need about " + memory_text(need) +
                    " of memory, more than the " + memory_text(avail) +
                    " available (MemAvailable, ulimit -v); choose a smaller " + key);
}

}  // namespace sph

// The end-of-run report of `sph run`: the summary line with the reference's values, and the warnings.
#include "run_report.h"

#include <omp.h>

#include <cstdio>
#include <string>
#include <vector>

#include "exit_codes.h"
#include "sph/thread_wait.h"
#include "summary_item.h"

namespace sph::cli {

void print_warnings(const World& world) {
  if (world.checks().warnings().empty()) return;
  std::fprintf(stderr, "warnings (%zu):\n", world.checks().warnings().size());
  for (const RunWarning& w : world.checks().warnings())
    std::fprintf(stderr, "  [%s] from step %lld (t = %g, %lld checks): %s\n", w.kind.c_str(),
                 static_cast<long long>(w.step), w.t, static_cast<long long>(w.times), w.message.c_str());
}

void print_summary(const RunOptions& opt, const RunConfig& cfg, const World& world, const World* b,
                   const std::optional<CompareSetup>& compare, double wall) {
  if (opt.quiet) return;
  const double psteps = static_cast<double>(world.steps()) * static_cast<double>(world.particles().size());
  std::printf("%s: t = %g after %lld steps, %zu particles, %.3f s wall, %.3g particle-steps/s, %d threads "
              "(the last step on %d; idle threads: %s)\n",
              cfg.scene->name.c_str(), world.time(), static_cast<long long>(world.steps()),
              world.particles().size(), wall, psteps / wall, omp_get_max_threads(), world.last_team(),
              thread_wait_policy().c_str());
  if (world.report().has_reference()) {
    const auto& cols = world.report().reference_columns();
    const std::vector<double> vals = world.report().reference_values();
    std::printf("reference at t = %g (%s):\n", world.time(), world.report().reference()->description().c_str());
    std::string line;
    for (std::size_t k = 0; k < cols.size(); ++k) line += summary_item(cols[k].name, vals[k]);
    std::printf("%s\n", line.c_str());
  }
  if (b) std::printf("%s\n", compare_summary(*b, *compare).c_str());
}

int energy_code(const RunConfig& cfg, const World& world, const World* b, bool sweep_beyond) {
  const bool a_bad = world.checks().energy_beyond_bound(cfg);
  const bool b_bad = b && b->checks().energy_beyond_bound(b->config());
  if (!a_bad && !b_bad && !sweep_beyond) return kOk;
  std::fprintf(stderr, "sph: the energy drifted beyond the scene's bound%s (see the warnings): the result is not to "
               "be trusted\n", a_bad ? (b || sweep_beyond ? " (run A)" : "") : b_bad ? " (run B)" : " (a sweep run)");
  return kInaccurate;
}

}  // namespace sph::cli

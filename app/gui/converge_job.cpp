#include "converge_job.h"

namespace sph::gui {

ConvergeJob::ConvergeJob(const RunConfig& base, const ConvergenceStudy& study)
    : total_(static_cast<int>(study.values.size())),
      counter_(std::make_shared<std::atomic<int>>(0)),
      finished_(*counter_) {
  auto counter = counter_;
  work_.start([base, study, counter] {
    return run_convergence(base, study, [counter](const ConvergenceRun&) { ++*counter; });
  });
}

}  // namespace sph::gui

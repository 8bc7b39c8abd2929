#include "converge_job.h"

#include <chrono>

namespace sph::gui {

ConvergeJob::ConvergeJob(const RunConfig& base, const ConvergenceStudy& study)
    : total_(static_cast<int>(study.values.size())),
      counter_(std::make_shared<std::atomic<int>>(0)),
      finished_(*counter_) {
  auto counter = counter_;
  future_ = std::async(std::launch::async, [base, study, counter] {
    return run_convergence(base, study, [counter](const ConvergenceRun&) { ++*counter; });
  });
}

ConvergeJob::~ConvergeJob() {
  if (future_.valid()) future_.wait();
}

bool ConvergeJob::poll() {
  if (!future_.valid()) return false;
  if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
  try {
    result_ = future_.get();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  return false;
}

}  // namespace sph::gui

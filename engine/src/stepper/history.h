// The running diagnostics of one World against time, kept small: a sample every `stride` steps; when the
// buffer is full, every other sample is dropped and the stride doubles (so memory stays bounded and the
// samples stay evenly spread in step number over the whole run).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/stepper.h"
#include "sph/world.h"

namespace sph::detail {

/// The world's diagnostics now, as one history point.
HistorySample history_sample(const World& w);

class History {
 public:
  explicit History(std::size_t capacity = 2048) : capacity_(capacity) {}
  /// Forget everything (new World).
  void clear();
  /// True if the step with this number should be sampled.
  bool due(std::int64_t step) const { return step % stride_ == 0; }
  void add(const HistorySample& s);
  const std::vector<HistorySample>& samples() const { return samples_; }
  std::int64_t stride() const { return stride_; }

 private:
  std::size_t capacity_;
  std::int64_t stride_ = 1;
  std::vector<HistorySample> samples_;
};

}  // namespace sph::detail

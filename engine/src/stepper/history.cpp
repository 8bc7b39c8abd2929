#include "history.h"

namespace sph::detail {

void History::clear() {
  samples_.clear();
  stride_ = 1;
}

void History::add(const HistorySample& s) {
  samples_.push_back(s);
  if (samples_.size() < capacity_) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < samples_.size(); i += 2) samples_[kept++] = samples_[i];
  samples_.resize(kept);
  stride_ *= 2;
}

}  // namespace sph::detail

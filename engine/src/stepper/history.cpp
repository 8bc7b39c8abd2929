#include "history.h"

#include <cmath>

namespace sph::detail {

HistorySample history_sample(const World& w) {
  const Diagnostics d = w.report().diagnostics();
  HistorySample s;
  s.t = d.t;
  s.E_kin = d.E_kin;
  s.E_int = d.E_int;
  s.E_pot = d.E_pot;
  s.E_tot = d.E_tot;
  s.P = std::sqrt(d.P[0] * d.P[0] + d.P[1] * d.P[1] + d.P[2] * d.P[2]);
  s.ref = w.report().reference_values();
  return s;
}

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

// RunChecks' part of a checkpoint: the blow-up guards' scales, the wall crossings not yet checked and
// the warnings so far, so a resumed run checks and warns as the saved run would have.
#include "io/byte_stream.h"
#include "sph/run_checks.h"

namespace sph {

void RunChecks::save(ByteWriter& w) const {
  w.put(dt_first_);
  w.put(energy_scale_); w.put(energy0_); w.put(worst_drift_);
  w.put<std::uint64_t>(crossings_.reflected); w.put<std::uint64_t>(crossings_.escaped);
  w.put<std::uint64_t>(crossings_.first_reflected); w.put<std::uint64_t>(crossings_.first_escaped);
  w.put<std::uint64_t>(warnings_.size());
  for (const RunWarning& x : warnings_) {
    w.put_string(x.kind); w.put_string(x.message); w.put(x.step); w.put(x.t); w.put(x.particle); w.put(x.times);
  }
}

void RunChecks::restore(ByteReader& r) {
  dt_first_ = r.get<double>();
  energy_scale_ = r.get<double>();
  energy0_ = r.get<double>();
  worst_drift_ = r.get<double>();
  crossings_.reflected = r.get<std::uint64_t>();
  crossings_.escaped = r.get<std::uint64_t>();
  crossings_.first_reflected = r.get<std::uint64_t>();
  crossings_.first_escaped = r.get<std::uint64_t>();
  const auto n_warnings = r.get<std::uint64_t>();
  if (n_warnings > r.left()) r.fail("too many warnings");
  warnings_.clear();
  for (std::uint64_t k = 0; k < n_warnings; ++k) {
    RunWarning x;
    x.kind = r.get_string();
    x.message = r.get_string();
    x.step = r.get<std::int64_t>();
    x.t = r.get<double>();
    x.particle = r.get<std::int64_t>();
    x.times = r.get<std::int64_t>();
    warnings_.push_back(std::move(x));
  }
}

}  // namespace sph

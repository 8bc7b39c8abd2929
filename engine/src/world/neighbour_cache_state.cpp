// NeighbourCache's part of a checkpoint: the kept lists and their build state, bit for bit, so a resumed
// run reuses (and rebuilds) its lists exactly when the saved run would have.
#include <algorithm>
#include <string>

#include "io/byte_stream.h"
#include "sph/neighbour_cache.h"

namespace sph {
namespace {

void put_list(ByteWriter& w, const NeighbourList& nl) {
  w.put_vec(nl.offset);
  w.put_vec(nl.index);
}

void get_list(ByteReader& r, NeighbourList& nl, std::size_t n, std::size_t total) {
  nl.offset = r.get_vec<std::uint32_t>();
  nl.index = r.get_vec<std::uint32_t>();
  if (nl.offset.empty() && nl.index.empty()) return;
  if (nl.offset.size() != n + 1 || nl.offset.front() != 0 || nl.offset.back() != nl.index.size() ||
      !std::is_sorted(nl.offset.begin(), nl.offset.end()))
    r.fail("the neighbour lists do not fit the particles");
  for (std::uint32_t j : nl.index)
    if (j >= total) r.fail("a neighbour index is out of range");
}

}  // namespace

void NeighbourCache::save_lists(ByteWriter& w) const {
  put_list(w, every_list());  // complete: a restored run has no grid to gather from
  put_list(w, exact_);
  w.put_bool(valid_);
  for (int k = 0; k < 3; ++k) w.put_vec(x_built_[k]);
  w.put_vec(h_limit_);
}

void NeighbourCache::save_rest(ByteWriter& w) const {
  w.put<std::uint64_t>(unwrapped_.size());
  for (const Unwrapped& u : unwrapped_) { w.put(u.i); w.put<std::int32_t>(u.axis); w.put(u.x); }
  w.put(builds_);
  w.put(h_overflows_);
}

void NeighbourCache::restore_lists(ByteReader& r, std::size_t n, std::size_t total) {
  get_list(r, nl_, n, total);
  gathered_.clear();
  missing_ = 0;
  get_list(r, exact_, n, total);
  valid_ = r.get_bool();
  for (int k = 0; k < 3; ++k) {
    x_built_[k] = r.get_vec<double>();
    if (!x_built_[k].empty() && x_built_[k].size() != n) r.fail("the lists' build positions do not fit");
  }
  h_limit_ = r.get_vec<double>();
}

void NeighbourCache::restore_rest(ByteReader& r, std::size_t n, std::size_t nf) {
  const auto n_unwrapped = r.get<std::uint64_t>();
  if (n_unwrapped > 3 * static_cast<std::uint64_t>(n)) r.fail("too many unwrapped coordinates");
  unwrapped_.clear();
  for (std::uint64_t k = 0; k < n_unwrapped; ++k) {
    Unwrapped u{};
    u.i = r.get<std::uint32_t>();
    u.axis = r.get<std::int32_t>();
    u.x = r.get<double>();
    if (u.i >= nf || u.axis < 0 || u.axis > 2) r.fail("an unwrapped coordinate is out of range");
    unwrapped_.push_back(u);
  }
  builds_ = r.get<std::int64_t>();
  h_overflows_ = r.get<std::int64_t>();
}

}  // namespace sph

// World::save_state / restore_state: the whole state later steps (and reference values) depend on, for
// checkpoints. Scratch (neighbour-search workspace, timings, the team chooser) is left out: results
// never depend on it.
#include <algorithm>

#include "core/pipeline.h"
#include "core/stage.h"
#include "io/byte_stream.h"
#include "sph/checkpoint.h"
#include "sph/world.h"

namespace sph {
namespace {

constexpr std::uint32_t kStateTag = 0x53575331;  // "SWS1": the layout below

void put_arrays(ByteWriter& w, const std::vector<std::vector<double>>& a) {
  w.put<std::uint64_t>(a.size());
  for (const auto& v : a) w.put_vec(v);
}

std::vector<std::vector<double>> get_arrays(ByteReader& r) {
  const auto n = r.get<std::uint64_t>();
  if (n > r.left() / 8) r.fail("an array count is larger than the data left");
  std::vector<std::vector<double>> a(static_cast<std::size_t>(n));
  for (auto& v : a) v = r.get_vec<double>();
  return a;
}

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

std::string World::save_state() const {
  ByteWriter w;
  w.put<std::uint32_t>(kStateTag);
  // particles: sizes, fields, then every array at its full length (ghosts included)
  const Particles& p = p_;
  w.put<std::int32_t>(p.dim());
  w.put<std::uint64_t>(p.size());
  w.put<std::uint64_t>(p.fluid());
  w.put<std::uint64_t>(p.total());
  std::vector<std::uint8_t> fields;
  p.fields().for_each([&](Field f) { fields.push_back(static_cast<std::uint8_t>(f)); });
  w.put_vec(fields);
  for (int k = 0; k < 3; ++k) { w.put_vec(p.x[k]); w.put_vec(p.v[k]); w.put_vec(p.a[k]); }
  w.put_vec(p.id);
  w.put_vec(p.kind);
  w.put_vec(p.ghost_src);
  w.put_vec(p.ghost_flip);
  for (int k = 0; k < 3; ++k) w.put_vec(p.ghost_offset[k]);
  p.fields().for_each([&](Field f) { w.put_vec(p[f]); });
  // kept neighbour lists (Verlet state)
  put_list(w, nl_);
  put_list(w, exact_);
  w.put_bool(lists_valid_);
  for (int k = 0; k < 3; ++k) w.put_vec(x_built_[k]);
  w.put_vec(h_limit_);
  w.put_vec(by_id_);
  w.put<std::uint64_t>(unwrapped_.size());
  for (const Unwrapped& u : unwrapped_) { w.put(u.i); w.put<std::int32_t>(u.axis); w.put(u.x); }
  // counters and clocks
  w.put(list_builds_); w.put(h_overflows_);
  w.put(t_last_eval_); w.put(since_); w.put(t_); w.put(dt_last_); w.put(dt_first_);
  w.put(energy_scale_); w.put(energy0_); w.put(worst_drift_);
  w.put<std::uint64_t>(crossings_.reflected); w.put<std::uint64_t>(crossings_.escaped);
  w.put<std::uint64_t>(crossings_.first_reflected); w.put<std::uint64_t>(crossings_.first_escaped);
  w.put<std::uint64_t>(warnings_.size());
  for (const RunWarning& x : warnings_) {
    w.put_string(x.kind); w.put_string(x.message); w.put(x.step); w.put(x.t); w.put(x.particle); w.put(x.times);
  }
  w.put(step_); w.put(evaluations_);
  w.put_bool(current_); w.put_bool(rates_known_);
  const DensityStats& d = stats_->density;
  w.put(d.mean_iterations); w.put<std::int32_t>(d.max_iterations); w.put<std::uint64_t>(d.not_converged);
  w.put(d.first_not_converged); w.put<std::uint64_t>(d.bisections); w.put(d.mean_neighbours);
  w.put<std::uint64_t>(stats_->correction_fallbacks);
  // integrator history and the stages' own state
  put_arrays(w, integrator_->history());
  w.put_vec(reference_ ? reference_->saved_state() : std::vector<double>{});
  w.put<std::uint64_t>(pipeline_->stages().size());
  for (const auto& s : pipeline_->stages()) {
    w.put_string(std::string(s->name()));
    put_arrays(w, s->saved_state());
  }
  w.put<std::uint32_t>(kStateTag);
  return w.take();
}

void World::restore_state(const std::string& bytes, const std::string& what) {
  ByteReader r(bytes.data(), bytes.size(), what);
  if (r.get<std::uint32_t>() != kStateTag) r.fail("unknown world-state layout");
  const int dim = r.get<std::int32_t>();
  const auto n = static_cast<std::size_t>(r.get<std::uint64_t>());
  const auto nf = static_cast<std::size_t>(r.get<std::uint64_t>());
  const auto total = static_cast<std::size_t>(r.get<std::uint64_t>());
  if (dim != p_.dim()) r.fail("the state is " + std::to_string(dim) + "D, the scene " + std::to_string(p_.dim()) + "D");
  if (nf > n || n > total || total > bytes.size()) r.fail("inconsistent particle counts");
  FieldSet fields;
  for (std::uint8_t f : r.get_vec<std::uint8_t>()) {
    if (f >= kFieldCount) r.fail("unknown field number " + std::to_string(f));
    fields.add(static_cast<Field>(f));
  }
  if ((fields & pipeline_->fields()) != pipeline_->fields()) r.fail("the saved fields do not cover the scene's stages");
  // the particles: a fresh store of n real ones (fluid first), then every array at its full length
  Particles q(dim, n, fields);
  auto take = [&](auto& dst, std::size_t len) {
    using T = typename std::decay_t<decltype(dst)>::value_type;
    std::vector<T> v = r.template get_vec<T>();
    if (v.size() != len) r.fail("an array has " + std::to_string(v.size()) + " entries, expected " + std::to_string(len));
    dst = std::move(v);
  };
  std::array<std::vector<double>, 3> x, v, a;
  for (int k = 0; k < 3; ++k) { take(x[k], total); take(v[k], total); take(a[k], total); }
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> kind;
  take(id, total);
  take(kind, total);
  std::copy(kind.begin(), kind.begin() + static_cast<std::ptrdiff_t>(n), q.kind.begin());
  q.partition_by_kind();  // the saved order is already fluid first: this only counts the fluid
  if (q.fluid() != nf) r.fail("the particle kinds do not match the fluid count");
  q.resize_total(total);
  q.x = std::move(x); q.v = std::move(v); q.a = std::move(a);
  q.id = std::move(id); q.kind = std::move(kind);
  take(q.ghost_src, total - n);
  take(q.ghost_flip, total - n);
  for (int k = 0; k < 3; ++k) take(q.ghost_offset[k], total - n);
  for (std::uint32_t s : q.ghost_src)
    if (s >= n) r.fail("a ghost's source is out of range");
  fields.for_each([&](Field f) { take(q[f], total); });
  NeighbourList nl, exact;
  get_list(r, nl, n, total);
  get_list(r, exact, n, total);
  const bool lists_valid = r.get_bool();
  std::array<std::vector<double>, 3> x_built;
  for (int k = 0; k < 3; ++k) {
    x_built[k] = r.get_vec<double>();
    if (!x_built[k].empty() && x_built[k].size() != n) r.fail("the lists' build positions do not fit");
  }
  std::vector<double> h_limit = r.get_vec<double>();
  std::vector<std::uint32_t> by_id;
  take(by_id, n);
  for (std::uint32_t i : by_id)
    if (i >= n) r.fail("an output index is out of range");
  const auto n_unwrapped = r.get<std::uint64_t>();
  if (n_unwrapped > 3 * static_cast<std::uint64_t>(n)) r.fail("too many unwrapped coordinates");
  std::vector<Unwrapped> unwrapped;
  for (std::uint64_t k = 0; k < n_unwrapped; ++k) {
    Unwrapped u{};
    u.i = r.get<std::uint32_t>();
    u.axis = r.get<std::int32_t>();
    u.x = r.get<double>();
    if (u.i >= nf || u.axis < 0 || u.axis > 2) r.fail("an unwrapped coordinate is out of range");
    unwrapped.push_back(u);
  }
  const auto list_builds = r.get<std::int64_t>(), h_overflows = r.get<std::int64_t>();
  double clocks[8];
  for (double& c : clocks) c = r.get<double>();
  WallCrossings crossings;
  crossings.reflected = r.get<std::uint64_t>();
  crossings.escaped = r.get<std::uint64_t>();
  crossings.first_reflected = r.get<std::uint64_t>();
  crossings.first_escaped = r.get<std::uint64_t>();
  const auto n_warnings = r.get<std::uint64_t>();
  if (n_warnings > r.left()) r.fail("too many warnings");
  std::vector<RunWarning> warnings;
  for (std::uint64_t k = 0; k < n_warnings; ++k) {
    RunWarning x;
    x.kind = r.get_string();
    x.message = r.get_string();
    x.step = r.get<std::int64_t>();
    x.t = r.get<double>();
    x.particle = r.get<std::int64_t>();
    x.times = r.get<std::int64_t>();
    warnings.push_back(std::move(x));
  }
  const auto step = r.get<std::int64_t>(), evaluations = r.get<std::int64_t>();
  const bool current = r.get_bool(), rates_known = r.get_bool();
  EvalStats stats;
  stats.density.mean_iterations = r.get<double>();
  stats.density.max_iterations = r.get<std::int32_t>();
  stats.density.not_converged = r.get<std::uint64_t>();
  stats.density.first_not_converged = r.get<std::int64_t>();
  stats.density.bisections = r.get<std::uint64_t>();
  stats.density.mean_neighbours = r.get<double>();
  stats.correction_fallbacks = r.get<std::uint64_t>();
  const auto history = get_arrays(r);
  const auto reference_state = r.get_vec<double>();
  const auto n_stages = r.get<std::uint64_t>();
  if (n_stages != pipeline_->stages().size())
    r.fail("the state has " + std::to_string(n_stages) + " stages, the scene " +
           std::to_string(pipeline_->stages().size()));
  std::vector<std::vector<std::vector<double>>> stage_states;
  for (const auto& s : pipeline_->stages()) {
    const std::string name = r.get_string();
    if (name != s->name()) r.fail("stage '" + name + "' where the scene runs '" + std::string(s->name()) + "'");
    stage_states.push_back(get_arrays(r));
  }
  if (r.get<std::uint32_t>() != kStateTag || r.left() != 0) r.fail("the world state does not end where it should");

  // everything read and checked: take it over
  if (!integrator_->set_history(history)) r.fail("the integrator history does not fit this integrator");
  if (reference_ ? !reference_->restore_state(reference_state) : !reference_state.empty())
    r.fail("the reference's state does not fit this scene's reference");
  for (std::size_t k = 0; k < stage_states.size(); ++k)
    if (!pipeline_->stages()[k]->restore_state(stage_states[k]))
      r.fail("the state of stage '" + std::string(pipeline_->stages()[k]->name()) + "' does not fit");
  p_ = std::move(q);
  nl_.offset = std::move(nl.offset);
  nl_.index = std::move(nl.index);
  exact_.offset = std::move(exact.offset);
  exact_.index = std::move(exact.index);
  lists_valid_ = lists_valid;
  x_built_ = std::move(x_built);
  h_limit_ = std::move(h_limit);
  by_id_ = std::move(by_id);
  unwrapped_ = std::move(unwrapped);
  list_builds_ = list_builds;
  h_overflows_ = h_overflows;
  t_last_eval_ = clocks[0]; since_ = clocks[1]; t_ = clocks[2]; dt_last_ = clocks[3]; dt_first_ = clocks[4];
  energy_scale_ = clocks[5]; energy0_ = clocks[6]; worst_drift_ = clocks[7];
  crossings_ = crossings;
  warnings_ = std::move(warnings);
  step_ = step;
  evaluations_ = evaluations;
  current_ = current;
  rates_known_ = rates_known;
  *stats_ = stats;
}

}  // namespace sph

// World::save_state / restore_state: the whole state later steps (and reference values) depend on, for
// checkpoints, in a fixed layout: the particles, the neighbour cache's part (sph/neighbour_cache.h),
// the clocks, the run checks' part (sph/run_checks.h), the counters, then the integrator's and the
// stages' state. Scratch (neighbour-search workspace, timings, the team chooser) is left out: results
// never depend on it.
#include <algorithm>

#include "core/pipeline.h"
#include "core/stage.h"
#include "integrators/block_steps.h"
#include "io/byte_stream.h"
#include "sph/checkpoint.h"
#include "sph/world.h"

namespace sph {
namespace {

constexpr std::uint32_t kStateTag = 0x53575332;  // "SWS2": the layout below

void put_arrays(ByteWriter& w, const std::vector<std::vector<double>>& a) {
  w.put<std::uint64_t>(a.size());
  for (const auto& v : a) w.put_vec(v);
}

/// Reads a vector that must hold `len` entries.
template <class V>
void take(ByteReader& r, V& dst, std::size_t len) {
  V v = r.get_vec<typename V::value_type>();
  if (v.size() != len) r.fail("an array has " + std::to_string(v.size()) + " entries, expected " + std::to_string(len));
  dst = std::move(v);
}

std::vector<std::vector<double>> get_arrays(ByteReader& r) {
  const auto n = r.get<std::uint64_t>();
  if (n > r.left() / 8) r.fail("an array count is larger than the data left");
  std::vector<std::vector<double>> a(static_cast<std::size_t>(n));
  for (auto& v : a) v = r.get_vec<double>();
  return a;
}

}  // namespace

void World::save_particles(ByteWriter& w) const {
  // sizes, fields, then every array at its full length (ghosts included)
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
}

std::string World::save_state() const {
  ByteWriter w;
  w.put<std::uint32_t>(kStateTag);
  save_particles(w);
  lists_.save_lists(w);  // kept neighbour lists (Verlet state)
  w.put_vec(by_id_);
  lists_.save_rest(w);
  // clocks, the checks' state and counters
  w.put(t_last_eval_); w.put(since_); w.put(t_); w.put(dt_last_);
  checks_.save(w);
  w.put(step_); w.put(evaluations_); w.put(updates_);
  w.put_bool(current_); w.put_bool(rates_known_);
  const DensityStats& d = stats_->density;
  w.put(d.mean_iterations); w.put<std::int32_t>(d.max_iterations); w.put<std::uint64_t>(d.not_converged);
  w.put(d.first_not_converged); w.put<std::uint64_t>(d.bisections); w.put(d.mean_neighbours);
  w.put<std::uint64_t>(stats_->correction_fallbacks);
  // integrator history and the stages' own state
  put_arrays(w, block_ ? block_->history() : integrator_->history());
  w.put_vec(reference_ ? reference_->saved_state() : std::vector<double>{});
  w.put<std::uint64_t>(pipeline_->stages().size());
  for (const auto& s : pipeline_->stages()) {
    w.put_string(std::string(s->name()));
    put_arrays(w, s->saved_state());
  }
  w.put<std::uint32_t>(kStateTag);
  return w.take();
}

Particles World::read_particles(ByteReader& r, std::size_t bytes) const {
  const int dim = r.get<std::int32_t>();
  const auto n = static_cast<std::size_t>(r.get<std::uint64_t>());
  const auto nf = static_cast<std::size_t>(r.get<std::uint64_t>());
  const auto total = static_cast<std::size_t>(r.get<std::uint64_t>());
  if (dim != p_.dim()) r.fail("the state is " + std::to_string(dim) + "D, the scene " + std::to_string(p_.dim()) + "D");
  if (nf > n || n > total || total > bytes) r.fail("inconsistent particle counts");
  FieldSet fields;
  for (std::uint8_t f : r.get_vec<std::uint8_t>()) {
    if (f >= kFieldCount) r.fail("unknown field number " + std::to_string(f));
    fields.add(static_cast<Field>(f));
  }
  if ((fields & pipeline_->fields()) != pipeline_->fields()) r.fail("the saved fields do not cover the scene's stages");
  // a fresh store of n real particles (fluid first), then every array at its full length
  Particles q(dim, n, fields);
  std::array<std::vector<double>, 3> x, v, a;
  for (int k = 0; k < 3; ++k) { take(r, x[k], total); take(r, v[k], total); take(r, a[k], total); }
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> kind;
  take(r, id, total);
  take(r, kind, total);
  std::copy(kind.begin(), kind.begin() + static_cast<std::ptrdiff_t>(n), q.kind.begin());
  q.partition_by_kind();  // the saved order is already fluid first: this only counts the fluid
  if (q.fluid() != nf) r.fail("the particle kinds do not match the fluid count");
  q.resize_total(total);
  q.x = std::move(x); q.v = std::move(v); q.a = std::move(a);
  q.id = std::move(id); q.kind = std::move(kind);
  take(r, q.ghost_src, total - n);
  take(r, q.ghost_flip, total - n);
  for (int k = 0; k < 3; ++k) take(r, q.ghost_offset[k], total - n);
  for (std::uint32_t s : q.ghost_src)
    if (s >= n) r.fail("a ghost's source is out of range");
  fields.for_each([&](Field f) { take(r, q[f], total); });
  return q;
}

void World::restore_state(const std::string& bytes, const std::string& what) {
  // read in the order save_state() wrote; the parts take theirs over as they read (a state that does
  // not fit leaves the world unusable, as documented)
  ByteReader r(bytes.data(), bytes.size(), what);
  if (r.get<std::uint32_t>() != kStateTag) r.fail("unknown world-state layout");
  Particles q = read_particles(r, bytes.size());
  const std::size_t n = q.size(), nf = q.fluid(), total = q.total();
  lists_.restore_lists(r, n, total);
  std::vector<std::uint32_t> by_id;
  take(r, by_id, n);
  for (std::uint32_t i : by_id)
    if (i >= n) r.fail("an output index is out of range");
  lists_.restore_rest(r, n, nf);
  double clocks[4];
  for (double& c : clocks) c = r.get<double>();
  checks_.restore(r);
  const auto step = r.get<std::int64_t>(), evaluations = r.get<std::int64_t>(), updates = r.get<std::int64_t>();
  const bool current = r.get_bool(), rates_known = r.get_bool();
  EvalStats stats;
  stats.density.mean_iterations = r.get<double>();
  stats.density.max_iterations = r.get<std::int32_t>();
  stats.density.not_converged = r.get<std::uint64_t>();
  stats.density.first_not_converged = r.get<std::int64_t>();
  stats.density.bisections = r.get<std::uint64_t>();
  stats.density.mean_neighbours = r.get<double>();
  stats.correction_fallbacks = r.get<std::uint64_t>();
  restore_stages(r);
  p_ = std::move(q);
  by_id_ = std::move(by_id);
  t_last_eval_ = clocks[0]; since_ = clocks[1]; t_ = clocks[2]; dt_last_ = clocks[3];
  step_ = step;
  evaluations_ = evaluations;
  updates_ = updates;
  current_ = current;
  rates_known_ = rates_known;
  *stats_ = stats;
}

void World::restore_stages(ByteReader& r) {
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
  if (block_ ? !block_->set_history(history) : !integrator_->set_history(history))
    r.fail("the integrator history does not fit this integrator");
  if (reference_ ? !reference_->restore_state(reference_state) : !reference_state.empty())
    r.fail("the reference's state does not fit this scene's reference");
  for (std::size_t k = 0; k < stage_states.size(); ++k)
    if (!pipeline_->stages()[k]->restore_state(stage_states[k]))
      r.fail("the state of stage '" + std::string(pipeline_->stages()[k]->name()) + "' does not fit");
}

}  // namespace sph

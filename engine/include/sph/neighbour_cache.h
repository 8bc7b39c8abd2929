// The neighbour lists a World keeps between evaluations (Verlet lists with a skin, ghosts included):
// when they still fit, when to rebuild them, and the periodic coordinates moved back to the image of
// the build while the stages run. Owned by World; its counters are read through World::neighbours().
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sph/domain.h"
#include "sph/fields.h"
#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/particles.h"
#include "sph/physics.h"

namespace sph {

class ByteReader;
class ByteWriter;

/// What one preparation of the lists needs to know about the run beyond the particles.
struct ListRequest {
  const Domain& domain;
  const Kernel& kernel;
  HMode smoothing;           ///< sets how far beyond h the lists reach
  const FieldSet& shared;    ///< fields copied to the ghosts before the stages run
  bool exact;                ///< a copy filtered to the support is wanted (exact())
  bool have_rates;           ///< an evaluation under the current parameters set dh/dt
  double since;              ///< time since that evaluation (0 when unknown)
  double dt_last;            ///< the last step's dt (0 before the first)
  bool by_rows = false;      ///< gather each new list only when need() asks for it (Pipeline::lists_by_rows)
};

class NeighbourCache {
 public:
  /// Ghosts and lists for the current state: the kept lists while they fit (their periodic coordinates
  /// moved back to the build's image until rewrap()), else new ones. Throws GhostOverflow.
  void prepare(Particles& p, const ListRequest& rq);
  /// Restores the coordinates prepare() moved.
  void rewrap(Particles& p);
  /// The lists to hand the stages: exact() when they asked for lists filtered to the support. With
  /// ListRequest::by_rows, only the lists need() asked for since the build are there; the others are empty.
  const NeighbourList& lists(bool exact) const { return exact ? exact_ : nl_; }
  /// Gathers the lists of `rows` (increasing) that are not there yet, as the build would have given them.
  void need(std::span<const std::uint32_t> rows);
  /// Every list, gathered where it was not yet (for readers of all lists: checkpoints, the vorticity).
  const NeighbourList& every_list() const;
  /// The largest h each particle's list covers.
  const std::vector<double>& h_limit() const { return h_limit_; }
  /// The lists must be rebuilt at the next preparation (new parameters, or an h outgrew its list).
  void invalidate() { valid_ = false; }
  /// An evaluation found an h beyond its list and runs again on new lists.
  void overflowed() { valid_ = false; ++h_overflows_; }
  /// Drops the lists (the particles were replaced by a set of another size).
  void clear();
  /// Follows a permutation of the real particles (new index k holds old order[k]).
  void permute(const std::vector<std::uint32_t>& order);

  /// Off: new lists at every evaluation (tests comparing against the kept lists).
  void set_reuse(bool on) { reuse_ = on; }
  /// Candidate pairs in the current lists (self included).
  std::size_t pairs() const { return nl_.pairs(); }
  std::int64_t builds() const { return builds_; }          ///< list builds so far
  std::int64_t h_overflows() const { return h_overflows_; }  ///< evaluations run again (overflowed())

  /// Checkpoint layout, in two parts (the particles' output order sits between them): the lists with
  /// their build state, then the moved coordinates and the counters. Reads check sizes against n real
  /// particles (nf of them fluid) and `total` with the ghosts; a misfit throws CheckpointError.
  void save_lists(ByteWriter& w) const;
  void save_rest(ByteWriter& w) const;
  void restore_lists(ByteReader& r, std::size_t n, std::size_t total);
  void restore_rest(ByteReader& r, std::size_t n, std::size_t nf);

 private:
  bool fits(const Particles& p, const Domain& d, double support, double since) const;
  void unwrap(Particles& p, const Domain& d);
  void build(Particles& p, const ListRequest& rq);

  /// A periodic coordinate wrapped since the lists were built, moved back to its image of the build for
  /// the stages and restored after them (x is its wrapped value).
  struct Unwrapped {
    std::uint32_t i;
    int axis;
    double x;
  };
  mutable NeighbourList nl_;
  NeighbourList exact_;                         ///< nl_ filtered to the support, for stages that ask for it
  std::vector<double> h_limit_;
  bool valid_ = false;                          ///< nl_ may be reused (while fits())
  bool reuse_ = true;                           ///< set_reuse
  std::array<std::vector<double>, 3> x_built_;  ///< real particles' positions when the lists were built
  std::vector<double> reach_h_;                 ///< h_limit of every particle and ghost, at the build
  double radius_ = 0.0;                         ///< the build's search radius, times reach_h_
  // With ListRequest::by_rows: which lists are gathered (a cache of the build: gathering one later gives
  // the same list, so every_list() may fill it in a const context)
  mutable std::vector<std::uint8_t> gathered_;
  mutable std::size_t missing_ = 0;             ///< lists not gathered yet
  void gather(std::span<const std::uint32_t> rows) const;
  std::vector<Unwrapped> unwrapped_;
  std::int64_t builds_ = 0;
  std::int64_t h_overflows_ = 0;
};

}  // namespace sph

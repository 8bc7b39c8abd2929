// What the gravity solvers read (the real particles 0..n-1 of a store: masses, positions, h) and what
// they write (accelerations and potentials per unit G, and the shortest pair dynamical time).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/particles.h"

namespace sph::gravity {

struct Sources {
  const std::array<std::vector<double>, 3>& x;
  const std::vector<double>& m;
  const std::vector<double>& h;
  std::size_t n;  ///< particles 0..n-1 attract each other
  int dim;
  /// The sinks (individual time steps): a flag per particle, nonzero where its acceleration is wanted;
  /// null: every particle. All n particles stay sources.
  const std::uint8_t* active = nullptr;
  static Sources of(const Particles& p) { return {p.x, p[Field::Mass], p[Field::H], p.fluid(), p.dim()}; }
};

struct Result {
  std::array<std::vector<double>, 3> a;  ///< acceleration [length/time^2]
  std::vector<double> phi;               ///< potential [length^2/time^2]
  /// per particle, a lower bound of the smallest r_eff^3 / (G (m_i + m_j)) over the pairs summed one by
  /// one [time^2] (the smallest r_eff with the largest m_j): the square of a two-body dynamical time
  /// (r_eff^2 = r^2 + softening^2); exact for two bodies
  std::vector<double> t2_pair;
  std::size_t pair_terms = 0, node_terms = 0;  ///< interactions evaluated (for benchmarks)
  void resize(std::size_t n);
  /// Ready for an evaluation of s: the sinks only (true) when s names them and this holds the last
  /// results of all s.n particles, which the others keep; else every particle, from zero (false).
  bool begin(const Sources& s) {
    if (s.active && phi.size() == s.n && t2_pair.size() == s.n && a[0].size() == s.n) {
      pair_terms = node_terms = 0;
      return true;
    }
    resize(s.n);
    return false;
  }
};

/// A walk's results per unit G in tree order (`walked`, its terms counted) added into out in storage
/// order (order[t] = the storage index of tree slot t), times G; only the sinks flagged in `active`
/// (storage order) when it is not null.
inline void add_from_tree_order(const Result& walked, const std::vector<std::uint32_t>& order, double G, Result& out,
                                const std::uint8_t* active = nullptr) {
  out.pair_terms += walked.pair_terms;
  out.node_terms += walked.node_terms;
  for (std::size_t t = 0; t < order.size(); ++t) {
    const std::uint32_t i = order[t];
    if (active && !active[i]) continue;
    for (int k = 0; k < 3; ++k) out.a[k][i] = G * walked.a[k][t];
    out.phi[i] = G * walked.phi[t];
    out.t2_pair[i] = walked.t2_pair[t] < 1e299 ? walked.t2_pair[t] / G : 1e300;
  }
}

inline void Result::resize(std::size_t n) {
  for (auto& c : a) c.assign(n, 0.0);
  phi.assign(n, 0.0);
  t2_pair.assign(n, 1e300);
  pair_terms = node_terms = 0;
}

}  // namespace sph::gravity

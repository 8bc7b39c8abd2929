// The gather of the vectorised force loops over the fluid (pair_block.h): per particle a its
// interacting pairs, their terms, the sums in list order and the write-back, each by the loop's `Pairs`
// (pair_standard.h, pair_standard_corrected.h), which provides Block, kColumns, kThreeD and kCont and
// self(i), terms(a, b, np), sum(a, b, np) -> sums with .count, finish(a, sums, cont).
#pragma once
#include <memory>

#include "core/parallel.h"
#include "core/stage.h"
#include "continuity_output.h"
#include "pair_block.h"

namespace sph {

/// R2: (support h)^2 of every particle (gather_pairs); skip_walls: without wall particles. With kCont,
/// the continuity rate's neighbour statistics too.
template <class Pairs>
void pair_loop(StageContext& c, const Pairs& pairs, const double* R2, bool skip_walls) {
  constexpr bool Cont = Pairs::kCont;
  Particles& p = c.p;
  const std::size_t n = p.fluid();
  std::unique_ptr<ContinuityOutput> cont;
  if constexpr (Cont) cont = std::make_unique<ContinuityOutput>(p, c.prm);
  double sum_nb = 0.0;
#pragma omp parallel reduction(+ : sum_nb) if (p.size() >= kParallelMin)
  {
  typename Pairs::Block b;  // this thread's pairs of i
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
  for (std::size_t row = 0; row < c.rows(n); ++row) {  // the active particles (individual time steps)
    const std::size_t i = c.row(row);
    const auto a = pairs.self(i);
    const std::size_t np = gather_pairs<Pairs::kColumns, Pairs::kThreeD>(p, R2, i, c.nl.of(i), skip_walls, b);
    pairs.terms(a, b, np);
    const auto t = pairs.sum(a, b, np);
    pairs.finish(a, t, cont.get());
    if constexpr (Cont) sum_nb += t.count;
  }
  }
  if constexpr (Cont) ContinuityOutput::finish(c, sum_nb, c.rows(n));
}

}  // namespace sph

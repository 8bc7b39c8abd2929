// Neighbour lists gathered row by row (individual time steps: an evaluation visits only the active
// particles and their neighbours). The grid of one build is kept, and each row is gathered from it and
// from the positions of that build, so a row is the same whenever it is gathered: the lists, and so
// the run, do not depend on which rows were asked for first.
#include <omp.h>

#include "cell_grid.h"
#include "core/parallel.h"

namespace sph {

void build_neighbour_grid(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out) {
  if (!out.work) out.work = std::make_shared<NeighbourWorkspace>();
  build_grid(p, h, radius, out.work->grid);
  out.offset.assign(p.size() + 1, 0);
  out.index.clear();
}

void gather_neighbour_rows(const std::array<std::vector<double>, 3>& x, const std::vector<double>& h, double radius,
                           std::span<const std::uint32_t> rows, NeighbourList& out) {
  const std::size_t nr = rows.size(), n = out.offset.size() - 1;
  if (nr == 0) return;
  const CellGrid& g = out.work->grid;
  // the new rows, each thread a contiguous block of them, concatenated in block order
  std::vector<std::uint32_t> fresh, at(nr + 1, 0);
  // a row costs hundreds of ns, so a team pays off from far fewer rows than a loop over particles does
  constexpr std::size_t kRowsForTeam = 256;
  const int T = nr >= kRowsForTeam ? omp_get_max_threads() : 1;
  std::vector<std::vector<std::uint32_t>> part(T);
  std::vector<std::size_t> base(T + 1, 0);
#pragma omp parallel num_threads(T)
  for (int t = omp_get_thread_num(); t < T; t += omp_get_num_threads()) {  // block t, whatever the team
    const std::size_t b = nr * t / T, e = nr * (t + 1) / T;
    std::vector<std::uint32_t>& local = part[t];
    local.resize(64 * (e - b) + 1024);
    std::size_t used = 0;
    for (std::size_t k = b; k < e; ++k) {
      const std::uint32_t i = rows[k];
      at[k] = static_cast<std::uint32_t>(used);  // within the block for now
      used = gather_neighbours(g, x[0][i], x[1][i], x[2][i], h[i], radius, local, used);
    }
    local.resize(used);
    base[t + 1] = used;
  }
  for (int t = 0; t < T; ++t) base[t + 1] += base[t];
  fresh.resize(base[T]);
  for (int t = 0; t < T; ++t) {
    std::copy(part[t].begin(), part[t].end(), fresh.begin() + static_cast<std::ptrdiff_t>(base[t]));
    const std::size_t b = nr * t / T, e = nr * (t + 1) / T;
    for (std::size_t k = b; k < e; ++k) at[k] += static_cast<std::uint32_t>(base[t]);
  }
  at[nr] = static_cast<std::uint32_t>(base[T]);
  // merge: the old rows keep their content, the new ones take their place in index order
  std::vector<std::uint32_t> len(n), offset(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) len[i] = out.offset[i + 1] - out.offset[i];
  for (std::size_t k = 0; k < nr; ++k) len[rows[k]] = at[k + 1] - at[k];
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + len[i];
  std::vector<std::uint32_t> index(offset[n]);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t b = out.offset[i], e = out.offset[i + 1];
    std::copy(out.index.begin() + b, out.index.begin() + e, index.begin() + offset[i]);
  }
#pragma omp parallel for schedule(static) if (nr >= kParallelMin)
  for (std::size_t k = 0; k < nr; ++k)
    std::copy(fresh.begin() + at[k], fresh.begin() + at[k + 1], index.begin() + offset[rows[k]]);
  out.offset.swap(offset);
  out.index.swap(index);
}

}  // namespace sph

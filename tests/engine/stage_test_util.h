// Running one stage of the pipeline on a hand-made particle set (white-box tests of engine/src/physics).
#pragma once
#include <cmath>
#include <memory>
#include <vector>

#include "core/pipeline.h"
#include "core/stage.h"
#include "core/stages.h"
#include "sph/domain.h"
#include "sph/neighbours.h"

namespace sph::test {

/// Particles, their ghosts and neighbour lists, and a context to run stages with.
struct StageBench {
  Params prm;
  Kernel kernel;
  Domain domain;
  Particles p;
  NeighbourList nl;
  std::vector<double> h_limit;
  EvalStats stats;
  double spacing = 0.0;

  StageBench(const Params& params, int dim, std::size_t n, FieldSet fields)
      : prm(params), kernel(params.kernel.type, dim), p(dim, n, fields) {}

  /// Ghosts (for the domain's periodic/mirror axes), copies of `shared`, neighbour lists (1.2 h skin).
  void prepare(FieldSet shared) {
    double hmax = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) hmax = std::max(hmax, p[Field::H][i]);
    make_ghosts(domain, kernel.support() * 1.2 * hmax, p);
    copy_ghost_velocity(p);
    copy_ghost_fields(p, shared.add(Field::Mass).add(Field::H));
    build_neighbours(p, p[Field::H], kernel.support() * 1.2, nl);
    h_limit.assign(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) h_limit[i] = 1.2 * p[Field::H][i];
  }
  StageContext context() {
    return StageContext{prm, kernel, domain, p, nl, h_limit, 1.3, spacing, 0.0, stats};
  }
  /// Runs the stage and copies what it shares to the ghosts.
  bool run(Stage& s) {
    StageContext c = context();
    const bool ok = s.run(c);
    copy_ghost_fields(p, s.shares());
    return ok;
  }
  /// Runs every stage of prm.physics in pipeline order, as World::evaluate does (after prepare()).
  void run_pipeline() {
    Pipeline pl(prm, p.dim());
    p.add_fields(pl.fields());
    for (const auto& s : pl.stages()) run(*s);
  }
};

/// A bench whose particles have every field of prm.physics's pipeline.
inline FieldSet pipeline_fields(const Params& prm, int dim) { return Pipeline(prm, dim).fields(); }

/// A jittered square lattice of n x n particles of spacing dx in [0, n dx]^2 (deterministic).
inline void jittered_lattice(Particles& p, std::size_t n, double dx, double jitter, double h, double rho) {
  std::uint64_t s = 12345;
  auto rnd = [&] {  // splitmix64 in [-0.5, 0.5)
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  };
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = j * n + i;
      p.x[0][k] = (i + 0.5 + jitter * rnd()) * dx;
      p.x[1][k] = (j + 0.5 + jitter * rnd()) * dx;
      p[Field::Mass][k] = rho * dx * dx;
      p[Field::H][k] = h;
      if (p.has(Field::Density)) p[Field::Density][k] = rho;
    }
}

}  // namespace sph::test

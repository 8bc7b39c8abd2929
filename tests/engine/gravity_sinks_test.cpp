// Self-gravity for some sinks only (individual time steps: Sources::active, Result::begin): for the fast
// multipole method, the Barnes-Hut tree (with and without its relative guard) and direct summation, with
// Plummer and kernel softening, every sink's acceleration, potential and pair time have the bits of a
// full evaluation, every other particle keeps the values it had, and fewer terms are summed.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

#include "gravity/barnes_hut.h"
#include "gravity/direct_sum.h"
#include "gravity/fmm.h"
#include "gravity_test_util.h"

namespace sph::gravity {
namespace {

enum class Solver { Fmm, Tree, TreeGuarded, Direct };

void evaluate(Solver solver, const Sources& s, const PairLaw& law, Result& out) {
  if (solver == Solver::Direct) return direct_sum(s, law, 1.0, out);
  if (solver == Solver::Fmm) {
    FastMultipole f;
    f.build(s);
    return f.evaluate(s, law, 1.0, 0.7, out, 0.0);
  }
  BarnesHutTree t;
  t.build(s);
  t.evaluate(s, law, 1.0, 0.6, out, solver == Solver::TreeGuarded ? 1e-3 : 0.0);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Case {
  Solver solver;
  bool kernel;
};

std::string name_of(const Case& c) {
  const char* names[] = {"Fmm", "Tree", "TreeGuarded", "Direct"};
  return std::string(names[static_cast<int>(c.solver)]) + (c.kernel ? "Kernel" : "Plummer");
}

class GravitySinks : public ::testing::TestWithParam<Case> {};

TEST_P(GravitySinks, SinksGetTheFullEvaluationsBitsAndTheOthersKeepTheirs) {
  const Case c = GetParam();
  const Particles p = test::sphere(3000, false, 11, 0.03);
  const KernelSoftening ks(KernelType::M4);
  PairLaw law;
  law.eps2 = 0.01 * 0.01;
  if (c.kernel) {
    law.kind = Softening::Kernel;
    law.kernel = &ks;
  }
  Sources s = Sources::of(p);
  Result full;
  evaluate(c.solver, s, law, full);
  // one particle in five a sink, in runs (as block levels group neighbours) and alone
  std::vector<std::uint8_t> sink(s.n, 0);
  std::mt19937_64 rng(5);
  for (std::size_t i = 0; i < s.n; ++i) sink[i] = (i / 40) % 7 == 0 || rng() % 17 == 0 ? 1 : 0;
  Result part;  // the last results: a marker the sinks must overwrite and the others keep
  part.resize(s.n);
  for (std::size_t i = 0; i < s.n; ++i) {
    for (int k = 0; k < 3; ++k) part.a[k][i] = -7.0 - k;
    part.phi[i] = 3.0;
    part.t2_pair[i] = 5.0;
  }
  s.active = sink.data();
  evaluate(c.solver, s, law, part);
  std::size_t sinks = 0, wrong = 0, moved = 0;
  for (std::size_t i = 0; i < s.n; ++i) {
    if (sink[i]) {
      ++sinks;
      bool ok = same_bits(part.phi[i], full.phi[i]) && same_bits(part.t2_pair[i], full.t2_pair[i]);
      for (int k = 0; k < 3; ++k) ok = ok && same_bits(part.a[k][i], full.a[k][i]);
      wrong += ok ? 0 : 1;
    } else {
      bool kept = part.phi[i] == 3.0 && part.t2_pair[i] == 5.0;
      for (int k = 0; k < 3; ++k) kept = kept && part.a[k][i] == -7.0 - k;
      moved += kept ? 0 : 1;
    }
  }
  EXPECT_GT(sinks, s.n / 8);
  EXPECT_LT(sinks, s.n / 3);
  EXPECT_EQ(wrong, 0u) << "sinks whose results differ from the full evaluation's";
  EXPECT_EQ(moved, 0u) << "other particles whose results changed";
  EXPECT_LT(part.pair_terms + part.node_terms, full.pair_terms + full.node_terms);
}

TEST(GravitySinks, WithoutTheLastResultsEveryParticleIsEvaluated) {
  const Particles p = test::sphere(500, true);
  Sources s = Sources::of(p);
  std::vector<std::uint8_t> sink(s.n, 0);
  sink[3] = 1;
  s.active = sink.data();
  Result out;  // empty: nothing to keep
  FastMultipole f;
  f.build(s);
  f.evaluate(s, PairLaw{}, 1.0, 0.7, out, 0.0);
  std::size_t zero = 0;
  for (std::size_t i = 0; i < s.n; ++i) zero += out.phi[i] == 0.0 ? 1 : 0;
  EXPECT_EQ(zero, 0u);
}

INSTANTIATE_TEST_SUITE_P(Solvers, GravitySinks,
                         ::testing::Values(Case{Solver::Fmm, false}, Case{Solver::Fmm, true}, Case{Solver::Tree, false},
                                           Case{Solver::TreeGuarded, true}, Case{Solver::Direct, false},
                                           Case{Solver::Direct, true}),
                         [](const auto& info) { return name_of(info.param); });

}  // namespace
}  // namespace sph::gravity

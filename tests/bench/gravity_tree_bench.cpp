// Barnes-Hut against direct summation on a Plummer sphere (softening 0.01 of its scale): the cost of a
// tree build plus walk from N = 1e3 to 1e5 (with the interactions per particle, so the N log N growth
// shows), and its force error against direct summation at theta = 0.3, 0.5, 0.7, 1.0 (on a sample of
// 1000 particles for large N: direct summation for those targets only). The walk includes the relative
// guard's coarse estimate pass (gravity.tol = 1e-3, the default); terms/part / log2 N levels off when
// the cost grows as N log N.
// Usage: gravity_tree_bench [N ...]   (default 1000 3000 10000 30000 100000)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "gravity/barnes_hut.h"
#include "gravity/direct_sum.h"
#include "gravity_bench_util.h"
#include "gravity_test_util.h"

using namespace sph;
using namespace sph::gravity;

using bench::direct_at;
using bench::seconds_since;

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes;
  for (int k = 1; k < argc; ++k) sizes.push_back(static_cast<std::size_t>(std::atof(argv[k])));
  if (sizes.empty()) sizes = {1000, 3000, 10000, 30000, 100000};
  const double eps = 0.01;
  PairLaw law;
  law.eps2 = eps * eps;
  std::printf("Plummer sphere, eps = %.2g, %d threads; error = |a_tree - a_direct| / |a_direct| over %s\n", eps,
              omp_get_max_threads(), "min(N, 1000) sample particles");
  std::printf("%8s %6s %10s %10s %12s %12s %12s %10s %10s %10s\n", "N", "theta", "build s", "walk s", "terms/part",
              "/log2 N", "ns/term", "rms err", "99% err", "max err");
  for (std::size_t n : sizes) {
    const Particles p = sph::test::sphere(n, true, 12345, 0.0);
    const Sources s = Sources::of(p);
    std::vector<std::size_t> sample;
    const std::size_t stride = std::max<std::size_t>(1, n / 1000);
    for (std::size_t i = 0; i < n; i += stride) sample.push_back(i);
    const auto exact = direct_at(p, sample, law.eps2);
    for (double theta : {0.3, 0.5, 0.7, 1.0}) {
      BarnesHutTree t;
      Result r;
      auto t0 = std::chrono::steady_clock::now();
      t.build(s);
      const double build = seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      t.evaluate(s, law, 1.0, theta, r);
      const double walk = seconds_since(t0);
      std::vector<double> err;
      for (std::size_t k = 0; k < sample.size(); ++k) {
        const std::size_t i = sample[k];
        double d2 = 0, b2 = 0;
        for (int c = 0; c < 3; ++c) {
          d2 += (r.a[c][i] - exact[k][c]) * (r.a[c][i] - exact[k][c]);
          b2 += exact[k][c] * exact[k][c];
        }
        err.push_back(std::sqrt(d2 / b2));
      }
      std::sort(err.begin(), err.end());
      double rms = 0;
      for (double e : err) rms += e * e;
      rms = std::sqrt(rms / static_cast<double>(err.size()));
      const double terms = static_cast<double>(r.pair_terms + r.node_terms);
      std::printf("%8zu %6.2f %10.4f %10.4f %12.1f %12.2f %12.2f %10.2e %10.2e %10.2e\n", n, theta, build, walk,
                  terms / static_cast<double>(n), terms / static_cast<double>(n) / std::log2(static_cast<double>(n)),
                  1e9 * walk / terms * omp_get_max_threads(),
                  rms, err[static_cast<std::size_t>(0.99 * static_cast<double>(err.size() - 1))], err.back());
    }
  }
  return 0;
}

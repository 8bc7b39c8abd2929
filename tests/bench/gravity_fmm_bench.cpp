// The fast multipole method against the Barnes-Hut tree: time per force evaluation (build + walks) and
// the relative force error |a - a_direct| / |a_direct| (RMS, 99th percentile, largest) over a sample of
// 1000 particles, on a Plummer sphere (scale 1, eps = 0.01) and the rho ~ 1/r sphere (R = 1), at the
// solvers' settings given on the command line or their run defaults (gravity.fmm_theta, gravity.fmm_tol,
// gravity.fmm_order; gravity.theta, gravity.tol with --tree). Figures: tests/bench/README.md.
// Usage: gravity_fmm_bench [--sphere plummer|r1] [--order P] [--tol T] [--theta a,b,..] [--leaf L] [--tree] N ...
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gravity/barnes_hut.h"
#include "gravity/fmm.h"
#include "gravity_bench_util.h"
#include "gravity_test_util.h"
#include "sph/params.h"

using namespace sph;
using namespace sph::gravity;
using bench::direct_at;
using bench::seconds_since;

namespace {

struct Errors {
  double rms, p99, max;
};

Errors errors(const Result& r, const std::vector<std::size_t>& sample, const std::vector<std::array<double, 3>>& exact) {
  std::vector<double> err;
  for (std::size_t k = 0; k < sample.size(); ++k) {
    double d2 = 0, b2 = 0;
    for (int c = 0; c < 3; ++c) {
      d2 += (r.a[c][sample[k]] - exact[k][c]) * (r.a[c][sample[k]] - exact[k][c]);
      b2 += exact[k][c] * exact[k][c];
    }
    err.push_back(std::sqrt(d2 / b2));
  }
  std::sort(err.begin(), err.end());
  double rms = 0;
  for (double e : err) rms += e * e;
  return {std::sqrt(rms / static_cast<double>(err.size())),
          err[static_cast<std::size_t>(0.99 * static_cast<double>(err.size() - 1))], err.back()};
}

std::vector<double> list(const char* s) {
  std::vector<double> v;
  for (const char* p = s; *p;) {
    char* end;
    v.push_back(std::strtod(p, &end));
    p = *end == ',' ? end + 1 : end;
    if (end == p && *p) break;
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes;
  std::vector<double> thetas;
  bool plummer = true, tree = false;
  const GravityParams defaults;
  int order = defaults.fmm_order;
  std::uint32_t leaf = FastMultipole::kLeafSize;
  double tol = -1.0;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--sphere" && k + 1 < argc) plummer = std::string(argv[++k]) != "r1";
    else if (a == "--order" && k + 1 < argc) order = std::atoi(argv[++k]);
    else if (a == "--tol" && k + 1 < argc) tol = std::atof(argv[++k]);
    else if (a == "--theta" && k + 1 < argc) thetas = list(argv[++k]);
    else if (a == "--leaf" && k + 1 < argc) leaf = static_cast<std::uint32_t>(std::atoi(argv[++k]));
    else if (a == "--tree") tree = true;
    else sizes.push_back(static_cast<std::size_t>(std::atof(argv[k])));
  }
  if (sizes.empty()) sizes = {10000, 100000};
  if (thetas.empty()) thetas = {tree ? defaults.theta : defaults.fmm_theta};  // the run defaults
  if (tol < 0.0) tol = tree ? defaults.tol : defaults.fmm_tol;
  const double eps = 0.01;
  PairLaw law;
  law.eps2 = eps * eps;
  std::printf("%s sphere, eps = %.2g, %d threads, %s order %d, tol %.2g; error over min(N, 1000) particles\n",
              plummer ? "Plummer" : "rho ~ 1/r", eps, omp_get_max_threads(), tree ? "Barnes-Hut" : "FMM", order, tol);
  std::printf("%8s %6s %9s %9s %11s %11s %9s %9s %9s %9s\n", "N", "theta", "build s", "eval s", "cells/part",
              "pairs/part", "us/part", "rms err", "99% err", "max err");
  for (std::size_t n : sizes) {
    const Particles p = sph::test::sphere(n, plummer, 12345, 0.0);
    const Sources s = Sources::of(p);
    std::vector<std::size_t> sample;
    const std::size_t stride = std::max<std::size_t>(1, n / 1000);
    for (std::size_t i = 0; i < n; i += stride) sample.push_back(i);
    const auto exact = direct_at(p, sample, law.eps2);
    for (double theta : thetas) {
      Result r;
      double build = 0, eval = 0;
      for (int rep = 0; rep < 2; ++rep) {  // the second repetition's times: warm caches and pages
        auto t0 = std::chrono::steady_clock::now();
        BarnesHutTree t;
        FastMultipole f(order);
        if (tree) t.build(s); else f.build(s, leaf);
        build = seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
        if (tree) t.evaluate(s, law, 1.0, theta, r, tol); else f.evaluate(s, law, 1.0, theta, r, tol);
        eval = seconds_since(t0);
      }
      const Errors e = errors(r, sample, exact);
      const double N = static_cast<double>(n);
      std::printf("%8zu %6.2f %9.4f %9.4f %11.1f %11.1f %9.3f %9.2e %9.2e %9.2e\n", n, theta, build, eval,
                  static_cast<double>(r.node_terms) / N, static_cast<double>(r.pair_terms) / N,
                  1e6 * (build + eval) / N, e.rms, e.p99, e.max);
    }
  }
  return 0;
}

// This machine's limit for thread speed-ups (tests/bench/README.md): what T threads give over one on three loops
// with nothing else in them, so the engine's speed-ups can be quoted against what the machine allows.
//   thread_limit_bench [threads=2] [MiB per thread=256] [repeats=5]
//   compute   four independent multiply-add chains in registers (no memory traffic)
//   cache     random loads from 512 KiB per thread (inside a core's own L2 cache)
//   memory    a streaming sum over MiB per thread (far beyond the L3 cache: DRAM bandwidth)
// Every thread does the same work whatever the team, so the speed-up is T times one thread's time over
// the team's time (best of the repeats, 1 and T threads alternated). A loop limited by memory bandwidth
// cannot scale better than the "memory" line. Arguments that are not whole numbers in range: a message
// naming the argument and exit code 2.
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <vector>

namespace {

volatile double g_sink = 0.0;  // keeps the loops' results alive

/// Four independent chains x <- a x + b per thread: the FP units only.
void compute(int threads) {
  double sink = 0.0;
#pragma omp parallel num_threads(threads) reduction(+ : sink)
  {
    double a = 1.0 + 1e-9 * omp_get_thread_num(), b = 1.1, c = 1.2, d = 1.3;
    for (long i = 0; i < 100000000L; ++i) {
      a = a * 0.9999999 + 1e-7;
      b = b * 0.9999998 + 2e-7;
      c = c * 0.9999997 + 3e-7;
      d = d * 0.9999996 + 4e-7;
    }
    sink += a + b + c + d;
  }
  g_sink = g_sink + sink;
}

/// Random loads (index from a linear congruential generator) from each thread's own `doubles` values.
void loads(int threads, const std::vector<double>& data, std::size_t doubles) {
  double sink = 0.0;
  std::size_t mask = 1;
  while (2 * mask <= doubles) mask *= 2;
  --mask;
#pragma omp parallel num_threads(threads) reduction(+ : sink)
  {
    const double* p = data.data() + static_cast<std::size_t>(omp_get_thread_num()) * doubles;
    std::uint64_t s = 12345u + static_cast<std::uint64_t>(omp_get_thread_num());
    double s0 = 0.0, s1 = 0.0;
    for (long k = 0; k < (1L << 27); k += 2) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      s0 += p[(s >> 20) & mask];
      s1 += p[(s >> 40) & mask];
    }
    sink += s0 + s1;
  }
  g_sink = g_sink + sink;
}

/// A streaming sum over each thread's own `doubles` values, eight partial sums (bandwidth, not latency).
void stream(int threads, const std::vector<double>& data, std::size_t doubles, int passes) {
  double sink = 0.0;
#pragma omp parallel num_threads(threads) reduction(+ : sink)
  {
    const double* p = data.data() + static_cast<std::size_t>(omp_get_thread_num()) * doubles;
    for (int r = 0; r < passes; ++r) {
      double s[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      for (std::size_t k = 0; k + 8 <= doubles; k += 8)
        for (int l = 0; l < 8; ++l) s[l] += p[k + static_cast<std::size_t>(l)];
      for (double v : s) sink += v;
    }
  }
  g_sink = g_sink + sink;
}

template <class F>
double seconds(F&& f) {
  const double t0 = omp_get_wtime();
  f();
  return omp_get_wtime() - t0;
}

/// Argument k as a whole number in [lo, hi], `fallback` when absent; exits with 2 naming it otherwise.
long argument(int argc, char** argv, int k, const char* name, long fallback, long lo, long hi) {
  if (argc <= k) return fallback;
  char* end = nullptr;
  const long v = std::strtol(argv[k], &end, 10);
  if (end == argv[k] || *end != '\0' || v < lo || v > hi) {
    std::fprintf(stderr, "thread_limit_bench: %s must be a whole number from %ld to %ld, got '%s'\n", name, lo, hi,
                 argv[k]);
    std::exit(2);
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  const int team = static_cast<int>(argument(argc, argv, 1, "threads", 2, 2, 256));
  const auto mib = static_cast<std::size_t>(argument(argc, argv, 2, "MiB per thread", 256, 1, 4096));
  const int repeats = static_cast<int>(argument(argc, argv, 3, "repeats", 5, 1, 1000));
  const std::size_t small = 512 * 1024 / 8, big = mib * 1024 * 1024 / 8;
  std::vector<double> cache_data(small * static_cast<std::size_t>(team), 1.0);
  std::vector<double> stream_data(big * static_cast<std::size_t>(team), 1.0);  // touched: no page faults timed
  std::printf("speed-up of %d threads over one, same work per thread, best of %d (1 and %d alternated)\n", team,
              repeats, team);
  struct Loop {
    const char* name;
    double one = 1e300, many = 1e300;
  } loops[3] = {{"compute"}, {"cache"}, {"memory"}};
  for (int r = 0; r < repeats; ++r)
    for (int t : {1, team}) {
      const double tc = seconds([&] { compute(t); });
      const double tl = seconds([&] { loads(t, cache_data, small); });
      const double ts = seconds([&] { stream(t, stream_data, big, 2); });
      const double got[3] = {tc, tl, ts};
      for (int k = 0; k < 3; ++k) {
        double& best = t == 1 ? loops[k].one : loops[k].many;
        best = std::min(best, got[k]);
      }
    }
  for (const Loop& l : loops) std::printf("  %-8s %5.2fx\n", l.name, team * l.one / l.many);
  const double bytes = 2.0 * static_cast<double>(big) * 8.0;
  std::printf("  memory bandwidth: %.1f GB/s on one thread, %.1f GB/s on %d (%zu MiB per thread)\n",
              bytes / loops[2].one / 1e9, team * bytes / loops[2].many / 1e9, team, mib);
  return 0;
}

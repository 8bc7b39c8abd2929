// This machine's limit for an SPH pair loop (tests/bench/README.md): a tight M4 density sum in 2D over a cell list,
// written here with nothing else in it, so the engine's loops can be quoted as a ratio to it.
//   calibration_bench [N=200000] [repeats=5]
// N particles uniform in the unit square, h = 1.2 dx (M4, support 2h, about 18 neighbours); cells of
// side 2h, sorted by cell. Three forms of the same sum:
//   branchy    if (r^2 < 4h^2) rho += m w(q)        (a mispredicted branch per candidate)
//   clamped    rho += m w(q) with clamped powers   (no branch; w = 0 beyond the support)
//   SSE2 x2    the clamped form on two doubles at a time (GCC vector extensions): two partial sums
//   x4         the same on four doubles at a time: one AVX2 instruction per operation when the build
//              uses AVX2 (SPH_SIMD, the default on machines that run it), two SSE2 ones otherwise
// (Four partial sums in plain C++ measured 3.7x slower than "clamped" here: GCC turned the clamps back
// into branches. Only the measured forms are kept.)
// Reported: ns per candidate tested and ns per neighbour inside the support; the densities of the three
// forms agree to round-off (checked).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Cloud {
  std::vector<double> x, y;               ///< positions sorted by cell
  std::vector<std::uint32_t> start;       ///< first particle of each cell (size cells+1)
  int n_side = 1;                         ///< cells per axis
  double h = 0.0;
};

Cloud make_cloud(std::size_t n) {
  Cloud c;
  const double dx = 1.0 / std::sqrt(static_cast<double>(n));
  c.h = 1.2 * dx;
  c.n_side = std::max(1, static_cast<int>(1.0 / (2.0 * c.h)));
  std::uint64_t s = 12345;
  auto uniform = [&] {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  std::vector<double> px(n), py(n);
  std::vector<std::uint32_t> cell(n);
  const std::size_t ncell = static_cast<std::size_t>(c.n_side) * c.n_side;
  c.start.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    px[i] = uniform();
    py[i] = uniform();
    const int cx = std::min(c.n_side - 1, static_cast<int>(px[i] * c.n_side));
    const int cy = std::min(c.n_side - 1, static_cast<int>(py[i] * c.n_side));
    cell[i] = static_cast<std::uint32_t>(cy * c.n_side + cx);
    ++c.start[cell[i] + 1];
  }
  for (std::size_t k = 0; k < ncell; ++k) c.start[k + 1] += c.start[k];
  std::vector<std::uint32_t> fill(c.start.begin(), c.start.end() - 1);
  c.x.resize(n);
  c.y.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t slot = fill[cell[i]]++;
    c.x[slot] = px[i];
    c.y[slot] = py[i];
  }
  return c;
}

inline double clamp0(double t) { return t > 0.0 ? t : 0.0; }  // one maxsd instruction

inline double m4_clamped(double q) {  // seed 000 eq. 3.2.7 without sigma, as clamped powers
  const double t = clamp0(2.0 - q), u = clamp0(1.0 - q);
  return 0.25 * t * t * t - u * u * u;
}

/// Two doubles in one SSE2 register (GCC vector extension): the explicit SIMD form of the clamped sum.
typedef double v2df __attribute__((vector_size(16)));

inline v2df m4_clamped(v2df q) {
  const v2df zero = {0.0, 0.0};
  v2df t = 2.0 - q, u = 1.0 - q;
  t = t > zero ? t : zero;
  u = u > zero ? u : zero;
  return 0.25 * t * t * t - u * u * u;
}

/// Four doubles: one AVX register, or two SSE2 ones.
typedef double v4df __attribute__((vector_size(32)));

inline v4df m4_clamped(v4df q) {
  const v4df zero = {0.0, 0.0, 0.0, 0.0};
  v4df t = 2.0 - q, u = 1.0 - q;
  t = t > zero ? t : zero;
  u = u > zero ? u : zero;
  return 0.25 * t * t * t - u * u * u;
}

inline v4df sqrt4(v4df x) {
#ifdef __AVX__
  return __builtin_ia32_sqrtpd256(x);
#else
  v2df lo = {x[0], x[1]}, hi = {x[2], x[3]};
  lo = __builtin_ia32_sqrtpd(lo);
  hi = __builtin_ia32_sqrtpd(hi);
  return v4df{lo[0], lo[1], hi[0], hi[1]};
#endif
}

enum class Form { Branchy, Clamped, Simd, Simd4 };

/// Density of every particle (without sigma / h^2 and with m = 1); counts candidates and neighbours.
void density(const Cloud& c, Form form, std::vector<double>& rho, double& candidates, double& neighbours) {
  const double hinv = 1.0 / c.h, R2 = 4.0 * c.h * c.h;
  const std::size_t n = c.x.size();
  rho.assign(n, 0.0);
  std::size_t cand = 0, nb = 0;
  for (int cy = 0; cy < c.n_side; ++cy)
    for (int cx = 0; cx < c.n_side; ++cx) {
      const std::size_t cell = static_cast<std::size_t>(cy) * c.n_side + cx;
      for (std::uint32_t i = c.start[cell]; i < c.start[cell + 1]; ++i) {
        const double xi = c.x[i], yi = c.y[i];
        double lane[2] = {0.0, 0.0};
        double sum = 0.0;
        for (int oy = std::max(cy - 1, 0); oy <= std::min(cy + 1, c.n_side - 1); ++oy) {
          const std::size_t row = static_cast<std::size_t>(oy) * c.n_side;
          const std::uint32_t b = c.start[row + std::max(cx - 1, 0)];
          const std::uint32_t e = c.start[row + std::min(cx + 1, c.n_side - 1) + 1];  // three cells in a row
          cand += e - b;
          if (form == Form::Branchy) {
            for (std::uint32_t j = b; j < e; ++j) {
              const double dx = xi - c.x[j], dy = yi - c.y[j], r2 = dx * dx + dy * dy;
              if (r2 < R2) { sum += m4_clamped(std::sqrt(r2) * hinv); ++nb; }
            }
          } else if (form == Form::Clamped) {
            for (std::uint32_t j = b; j < e; ++j) {
              const double dx = xi - c.x[j], dy = yi - c.y[j];
              sum += m4_clamped(std::sqrt(dx * dx + dy * dy) * hinv);
            }
          } else if (form == Form::Simd) {
            std::uint32_t j = b;
            v2df acc = {0.0, 0.0};
            for (; j + 2 <= e; j += 2) {
              v2df px, py;
              __builtin_memcpy(&px, c.x.data() + j, sizeof px);
              __builtin_memcpy(&py, c.y.data() + j, sizeof py);
              const v2df dx = xi - px, dy = yi - py;
              acc += m4_clamped(__builtin_ia32_sqrtpd(dx * dx + dy * dy) * hinv);
            }
            lane[0] += acc[0];
            lane[1] += acc[1];
            for (; j < e; ++j) {
              const double dx = xi - c.x[j], dy = yi - c.y[j];
              lane[0] += m4_clamped(std::sqrt(dx * dx + dy * dy) * hinv);
            }
          } else {
            std::uint32_t j = b;
            v4df acc = {0.0, 0.0, 0.0, 0.0};
            for (; j + 4 <= e; j += 4) {
              v4df px, py;
              __builtin_memcpy(&px, c.x.data() + j, sizeof px);
              __builtin_memcpy(&py, c.y.data() + j, sizeof py);
              const v4df dx = xi - px, dy = yi - py, r2 = dx * dx + dy * dy;
              acc += m4_clamped(sqrt4(r2) * hinv);
            }
            lane[0] += (acc[0] + acc[1]) + (acc[2] + acc[3]);
            for (; j < e; ++j) {
              const double dx = xi - c.x[j], dy = yi - c.y[j];
              lane[0] += m4_clamped(std::sqrt(dx * dx + dy * dy) * hinv);
            }
          }
        }
        rho[i] = form == Form::Simd || form == Form::Simd4 ? lane[0] + lane[1] : sum;
      }
    }
  candidates = static_cast<double>(cand);
  neighbours = static_cast<double>(nb);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 200000;
  const int repeats = argc > 2 ? std::stoi(argv[2]) : 5;
  const Cloud c = make_cloud(n);
  std::vector<double> reference, rho;
  double cand = 0.0, nb = 0.0, unused = 0.0;
  density(c, Form::Branchy, reference, cand, nb);
  std::printf("M4 2D density sum, N = %zu, %.1f candidates and %.1f neighbours per particle, %d repeats (best)\n", n,
              cand / n, nb / n, repeats);
  const char* names[4] = {"branchy", "clamped", "SSE2 x2", "x4"};
  for (int f = 0; f < 4; ++f) {
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      density(c, static_cast<Form>(f), rho, unused, unused);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(rho[i] - reference[i]) / reference[i]);
    std::printf("  %-8s %6.2f ns per candidate  %6.2f ns per neighbour  (max relative difference %.1e)\n", names[f],
                1e9 * best / cand, 1e9 * best / nb, worst);
    if (worst > 1e-12) { std::printf("calibration_bench: the forms disagree\n"); return 1; }
  }
  return 0;
}

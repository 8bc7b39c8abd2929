// e^x written with plain arithmetic (tests/engine/exp_poly_test.cpp), so pair loops that use the Gaussian
// kernel vectorise: the C library's exp is an opaque call that keeps a loop scalar. Cody-Waite reduction
// x = k ln2 + r with |r| <= ln2/2, e^r by its Taylor polynomial to degree 13 (remainder below 5e-18
// relative), and 2^k put into the exponent bits. Relative error within 2 ulp of the exact value for -708
// <= x <= 709 (tested against std::exp); the same result on every target and vector width (no FMA:
// -ffp-contract=off).
#pragma once
#include <bit>
#include <cstdint>

namespace sph {

/// e^x for -708 <= x <= 709 (outside that range the result is not meaningful: callers clamp).
[[gnu::always_inline]] inline double exp_poly(double x) {
  constexpr double log2e = 1.4426950408889634074;
  constexpr double ln2_hi = 6.93147180369123816490e-01;  // ln 2 split so k ln2_hi is exact for |k| < 2^11
  constexpr double ln2_lo = 1.90821492927058770002e-10;
  constexpr double shifter = 0x1.8p52;                  // adding it rounds to an integer in the low bits
  const double kd_shifted = x * log2e + shifter;
  const double kd = kd_shifted - shifter;               // k = nearest integer to x / ln 2
  const double r = (x - kd * ln2_hi) - kd * ln2_lo;
  // Horner's rule, 1/13! ... 1/1!
  double p = 1.0 / 6227020800.0;
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // 2^k: k sits in the low bits of kd_shifted; add it to p's exponent field
  const std::uint64_t k = std::bit_cast<std::uint64_t>(kd_shifted) - std::bit_cast<std::uint64_t>(shifter);
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(p) + (k << 52));
}

}  // namespace sph

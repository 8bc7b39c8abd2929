// Range checks of the numeric flags: one message naming the bound, and NaN or inf refused (CLI11's own
// range checks let NaN through and print DBL_MAX in full).
#pragma once
#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

namespace sph::cli {

/// A finite number >= lo (strict: > lo).
inline CLI::Validator finite_from(double lo, bool strict) {
  const std::string bound = std::string(strict ? "> " : ">= ") + CLI::detail::to_string(lo);
  return CLI::Validator(
      [lo, strict, bound](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v)) return "expected a number, got " + text;
        if (!std::isfinite(v) || (strict ? !(v > lo) : !(v >= lo)))
          return "expected a finite number " + bound + ", got " + text;
        return {};
      },
      "NUMBER " + bound);
}

}  // namespace sph::cli

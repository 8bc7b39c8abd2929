// The error that stops a run: a non-finite value in the state, or a blow-up a check found while the
// state was still finite.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sph {

/// The run cannot go on: a NaN or inf appeared in the state (which particle (id), which field, at which
/// step), or a check found a blow-up that is still finite (the reason says which).
struct DivergedError : std::runtime_error {
  DivergedError(std::int64_t particle, std::int64_t step, double t, const std::string& field);
  /// A finite blow-up: `reason` is the whole explanation (it names the particle where there is one).
  DivergedError(std::int64_t particle, std::int64_t step, double t, const std::string& field, const std::string& reason);
  std::int64_t particle, step;
  double t;
  std::string field;
};

}  // namespace sph

// Per-particle fields: one array each, allocated only when a module of the scene needs it (SPH-EXA style).
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

namespace sph {

enum class Field : std::uint8_t {
  Mass,       ///< m [mass]
  Density,    ///< rho [mass/length^d], summation density (seed 000 eq. 3.2.17)
  H,          ///< smoothing length h [length]
  Omega,      ///< grad-h term Omega (seed 000 eq. 3.3.2) [dimensionless]
  Pressure,   ///< P [mass/(length^(d-2) time^2)] = (gamma-1) rho u
  Energy,     ///< specific internal energy u [length^2/time^2]
  EnergyRate, ///< du/dt [length^2/time^3]
  SoundSpeed, ///< c = sqrt(gamma P / rho) [length/time]
  SignalSpeed,///< max pairwise signal speed, for the CFL limit [length/time]
  Neighbours, ///< number of neighbours inside the particle's own support
  HIterations,///< Newton-Raphson iterations of the last density solve
  Count
};

constexpr std::size_t kFieldCount = static_cast<std::size_t>(Field::Count);

/// Bit set of fields.
struct FieldSet {
  std::uint32_t bits = 0;
  FieldSet& add(Field f) { bits |= 1u << static_cast<unsigned>(f); return *this; }
  bool has(Field f) const { return bits & (1u << static_cast<unsigned>(f)); }
  FieldSet operator|(FieldSet o) const { return {bits | o.bits}; }
};

struct FieldInfo {
  std::string_view key;    ///< short name used by --color-by and CSV headers
  std::string_view label;  ///< human label
};

constexpr std::array<FieldInfo, kFieldCount> kFieldInfo{{
    {"m", "mass m"},
    {"rho", "density rho"},
    {"h", "smoothing length h"},
    {"omega", "grad-h term Omega"},
    {"p", "pressure P"},
    {"u", "internal energy u"},
    {"dudt", "du/dt"},
    {"cs", "sound speed c"},
    {"vsig", "signal speed"},
    {"nneigh", "neighbour count"},
    {"hiter", "h iterations"},
}};

inline const FieldInfo& info(Field f) { return kFieldInfo[static_cast<std::size_t>(f)]; }

}  // namespace sph

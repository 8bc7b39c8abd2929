// Per-particle fields: one array each, allocated only when a stage of the scene's pipeline needs it
// (SPH-EXA style). Vector and tensor quantities are stored one component per field; their mirror
// parity (which wall reflections flip their sign) lets ghosts copy them correctly.
#pragma once
#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace sph {

enum class Field : std::uint8_t {
  Mass,        ///< m [mass]
  Density,     ///< rho [mass/length^d]: summation (seed 000 eq. 3.2.17) or continuity (seed 001 eq. 39)
  H,           ///< smoothing length h [length]
  Omega,       ///< grad-h term Omega (seed 000 eq. 3.3.2) [dimensionless]
  Pressure,    ///< P [mass/(length^(d-2) time^2)]
  Energy,      ///< specific internal energy u [length^2/time^2]
  EnergyRate,  ///< du/dt [length^2/time^3]
  SoundSpeed,  ///< c [length/time]
  SignalSpeed, ///< max pairwise signal speed, for the CFL limit [length/time]
  Neighbours,  ///< number of neighbours inside the particle's own support
  HIterations, ///< Newton-Raphson iterations of the last density solve
  DensityRate, ///< drho/dt of the continuity equation (seed 001 eq. 39) [mass/(length^d time)]
  Shepard,     ///< S = sum_b V_b W_ab, the order-0 kernel correction is W/S (seed 001 eq. 33) [dimensionless]
  CorrCX, CorrCY, CorrCZ,  ///< c = L grad S / S^2: the corrected gradient is G = A grad W - W c (seed 001 eq. 36) [1/length]
  CorrXX, CorrXY, CorrXZ, CorrYX, CorrYY, CorrYZ, CorrZX, CorrZY, CorrZZ,  ///< A = L / S, L of seed 001 eq. 35
  CorrFallback,  ///< 1 where the gradient correction was ill-conditioned and fell back to L = I
  XsphX, XsphY, XsphZ,  ///< drift dx/dt - v: XSPH's v* - v (seed 001 eq. 45), FPM upwind's -u/2 [length/time]
  VelGradXX, VelGradXY, VelGradXZ, VelGradYX, VelGradYY, VelGradYZ, VelGradZX, VelGradZY, VelGradZZ,  ///< dv_k/dx_l (seed 001 eq. 52) [1/time]
  Potential,   ///< gravitational potential phi at the particle [length^2/time^2]
  RestX,       ///< the FPM point's place in the initial set Gamma_0 (seed 002 Note 3.2) [length]
  HRate,       ///< dh/dt = -h/(d rho) drho/dt of a summation density (seed 000 eqs. 3.3.2, 3.5.1) [length/time]
  DivV,        ///< div v = -(1/(Omega rho)) sum_b m_b v_ab . grad W_ab(h_a) [1/time]
  CurlV,       ///< |curl v| = |(1/(Omega rho)) sum_b m_b v_ab x grad W_ab(h_a)| [1/time]
  ViscAlpha,   ///< artificial viscosity alpha of the particle (visc.switch) [dimensionless]
  GravZeta,    ///< zeta/Omega of kernel-softened gravity's grad-h term (Price & Monaghan 2007) [length^(d-1)]
  StepLevel,   ///< individual time steps: the level k of the particle's step, dt = block / 2^k [dimensionless]
  DfsphKappa,  ///< DFSPH: the density solve's P/rho of the last step, its warm start [length^2/time^2]
  DfsphKappaV, ///< DFSPH: the divergence solve's dt P/rho of the last step, its warm start [length^2/time]
  Count
};

constexpr std::size_t kFieldCount = static_cast<std::size_t>(Field::Count);

constexpr std::size_t index(Field f) { return static_cast<std::size_t>(f); }
/// Component k (0..2) of a vector field whose x component is `first`.
constexpr Field component(Field first, int k) { return static_cast<Field>(index(first) + static_cast<std::size_t>(k)); }
/// Component (k, l) of a 3x3 tensor field stored row by row from `first`.
constexpr Field component(Field first, int k, int l) {
  return static_cast<Field>(index(first) + static_cast<std::size_t>(3 * k + l));
}

/// A set of fields (any number of them).
class FieldSet {
 public:
  FieldSet() = default;
  FieldSet(std::initializer_list<Field> fields) { for (Field f : fields) add(f); }
  FieldSet& add(Field f) { bits_.set(index(f)); return *this; }
  /// Adds the components k < dim of a vector field, or (k, l) with k, l < dim of a tensor field: all three
  /// or nine by default.
  FieldSet& add_vector(Field first, int dim = 3) { for (int k = 0; k < dim; ++k) add(component(first, k)); return *this; }
  FieldSet& add_tensor(Field first, int dim = 3) {
    for (int k = 0; k < dim; ++k)
      for (int l = 0; l < dim; ++l) add(component(first, k, l));
    return *this;
  }
  bool has(Field f) const { return bits_.test(index(f)); }
  bool empty() const { return bits_.none(); }
  std::size_t count() const { return bits_.count(); }
  FieldSet operator|(FieldSet o) const { FieldSet r; r.bits_ = bits_ | o.bits_; return r; }
  FieldSet& operator|=(FieldSet o) { bits_ |= o.bits_; return *this; }
  FieldSet operator&(FieldSet o) const { FieldSet r; r.bits_ = bits_ & o.bits_; return r; }
  bool operator==(const FieldSet& o) const = default;
  /// Calls fn(Field) for every member, in enum order.
  template <class Fn>
  void for_each(Fn&& fn) const {
    for (std::size_t i = 0; i < kFieldCount; ++i)
      if (bits_.test(i)) fn(static_cast<Field>(i));
  }

 private:
  std::bitset<kFieldCount> bits_;
};

struct FieldInfo {
  std::string_view key;    ///< short name used by --color-by and CSV headers
  std::string_view label;  ///< human label
  std::uint8_t flip_axes;  ///< the value changes sign under a mirror of an odd number of these axes (bit k = axis k)
  bool display;            ///< offered as a colour-by field when allocated
  bool csv;                ///< written to particle files when allocated
};

namespace field_detail {
constexpr std::uint8_t ax(int k) { return static_cast<std::uint8_t>(1u << k); }
/// Tensor component (k, l) flips under a mirror of axis k or of axis l, not both: bits k xor l.
constexpr std::uint8_t tx(int k, int l) { return static_cast<std::uint8_t>(ax(k) ^ ax(l)); }
}  // namespace field_detail

constexpr std::array<FieldInfo, kFieldCount> kFieldInfo{{
    {"m", "mass m", 0, false, true},
    {"rho", "density rho", 0, true, true},
    {"h", "smoothing length h", 0, true, true},
    {"omega", "grad-h term Omega", 0, true, false},
    {"p", "pressure P", 0, true, true},
    {"u", "internal energy u", 0, true, true},
    {"dudt", "du/dt", 0, false, false},
    {"cs", "sound speed c", 0, true, false},
    {"vsig", "signal speed", 0, false, false},
    {"nneigh", "neighbour count", 0, true, false},
    {"hiter", "h iterations", 0, false, false},
    {"drhodt", "continuity drho/dt", 0, true, false},
    {"shepard", "kernel sum S = sum V W", 0, true, false},
    {"cx", "correction c_x = (L grad S)_x / S^2", field_detail::ax(0), false, false},
    {"cy", "correction c_y", field_detail::ax(1), false, false},
    {"cz", "correction c_z", field_detail::ax(2), false, false},
    {"Axx", "correction A_xx = L_xx / S", field_detail::tx(0, 0), false, false},
    {"Axy", "correction A_xy", field_detail::tx(0, 1), false, false},
    {"Axz", "correction A_xz", field_detail::tx(0, 2), false, false},
    {"Ayx", "correction A_yx", field_detail::tx(1, 0), false, false},
    {"Ayy", "correction A_yy", field_detail::tx(1, 1), false, false},
    {"Ayz", "correction A_yz", field_detail::tx(1, 2), false, false},
    {"Azx", "correction A_zx", field_detail::tx(2, 0), false, false},
    {"Azy", "correction A_zy", field_detail::tx(2, 1), false, false},
    {"Azz", "correction A_zz", field_detail::tx(2, 2), false, false},
    {"fallback", "gradient correction fell back (1)", 0, true, false},
    {"xsph_x", "XSPH correction x", field_detail::ax(0), false, false},
    {"xsph_y", "XSPH correction y", field_detail::ax(1), false, false},
    {"xsph_z", "XSPH correction z", field_detail::ax(2), false, false},
    {"dvxdx", "dv_x/dx", field_detail::tx(0, 0), false, false},
    {"dvxdy", "dv_x/dy", field_detail::tx(0, 1), false, false},
    {"dvxdz", "dv_x/dz", field_detail::tx(0, 2), false, false},
    {"dvydx", "dv_y/dx", field_detail::tx(1, 0), false, false},
    {"dvydy", "dv_y/dy", field_detail::tx(1, 1), false, false},
    {"dvydz", "dv_y/dz", field_detail::tx(1, 2), false, false},
    {"dvzdx", "dv_z/dx", field_detail::tx(2, 0), false, false},
    {"dvzdy", "dv_z/dy", field_detail::tx(2, 1), false, false},
    {"dvzdz", "dv_z/dz", field_detail::tx(2, 2), false, false},
    {"phi", "gravitational potential phi", 0, true, true},
    {"x0", "initial point x0 (Gamma_0)", 0, false, false},
    {"dhdt", "dh/dt", 0, false, false},
    {"divv", "velocity divergence div v", 0, true, false},
    {"curlv", "vorticity |curl v|", 0, true, false},
    {"alpha", "viscosity alpha (switch)", 0, true, true},
    {"zeta", "gravity grad-h term zeta/Omega", 0, false, false},
    {"level", "time-step level k: dt = block / 2^k", 0, true, true},
    {"kappa", "DFSPH density solve P/rho", 0, false, false},
    {"kappa_v", "DFSPH divergence solve P/rho", 0, false, false},
}};

inline const FieldInfo& info(Field f) { return kFieldInfo[index(f)]; }

}  // namespace sph

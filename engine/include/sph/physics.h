// The physics a scene runs: one option per slot of the step pipeline, "none" included. World::evaluate
// runs the chosen stages in a fixed order (density, smoothing length, EOS, wall pressure, corrections,
// XSPH, forces with viscosity and energy, continuity, wall forces, body force, self-gravity); a stage that is "none"
// is not run and its fields are not allocated. The choices are parameters (keys physics.SLOT).
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace sph {

/// How rho is obtained.
enum class DensityMode {
  None,
  Summation,   ///< rho_a = sum_b m_b W_ab(h_a) (seed 000 eq. 3.2.17), with h solved by Newton-Raphson or fixed
  Continuity,  ///< drho_a/dt = rho_a sum_b V_b v_ab . grad W_ab (seed 001 eq. 39): rho is evolved
  Volume,      ///< 1/V_a = sum_b W_ab, rho_a = m_a / V_a (seed 004): number density, for unequal masses
};
/// How h is obtained.
enum class HMode {
  Variable,  ///< h = eta (m/rho)^(1/d) solved with rho by Newton-Raphson, grad-h Omega terms (seed 000 eq. 3.5.1)
  Fixed,     ///< h kept at its initial value, Omega = 1
  Evolved,   ///< h = eta (m/rho)^(1/d) from the evolved (continuity) density at every evaluation
};
enum class EosType {
  None,
  IdealGas,    ///< P = (gamma - 1) rho u (seed 000 eq. 3.3.23)
  Tait,        ///< P = B [(rho/rho0)^gamma - 1] + p0, B = rho0 c0^2/gamma (seed 001 eq. 3; Cole 1948)
  Isothermal,  ///< P = c_s^2 rho (seed 003 eq. 3.72 with n -> infinity)
  Polytropic,  ///< P = K rho^gamma, gamma = 1 + 1/n (seed 003 eq. 3.72)
  /// Incompressible: no EOS; the pressure is solved for at every step so that the density stays rho0
  /// and the velocity divergence-free (DFSPH, Bender & Koschier 2017, IEEE TVCG 23, 1193; physics/dfsph_solver.h)
  Dfsph,
};
/// Momentum (and continuity) discretisation.
enum class ForceType {
  None,
  Standard,           ///< sum_b m_b (P_a/rho_a^2 + P_b/rho_b^2 + Pi_ab) grad W_ab (seed 001 eq. 44; seed 000 eq. 3.3.17)
  Corrected,          ///< (1/rho_a) sum_b V_b (T_b - T_a) grad* K0*_ab, stress form (seed 001 eqs. 48-52)
  StandardCorrected,  ///< the standard form with corrected kernel gradients (seed 001 eqs. 53-55)
};
enum class ViscType {
  None,
  Monaghan,   ///< artificial Pi_ab (seed 003 eq. 3.16; seed 001 eqs. 41-43)
  Laplacian,  ///< physical nu, Laplacian from first kernel derivatives (seed 004; Morris et al. 1997)
};
/// A time-dependent artificial viscosity: alpha per particle instead of the constant visc.alpha
/// (physics.viscosity = monaghan with the standard or standard-corrected forces; viscosity_switch.cpp).
enum class ViscSwitch {
  None,          ///< the constant alpha of visc.alpha
  Balsara,       ///< alpha f_a, f = |div v|/(|div v| + |curl v| + 1e-4 c/h) (Balsara 1995, JCP 121, 357)
  CullenDehnen,  ///< alpha raised ahead of shocks and decaying behind them (Cullen & Dehnen 2010, MNRAS 408, 669)
};
enum class Toggle { Off, On };
enum class BodyForce {
  None,
  Uniform,  ///< constant acceleration g (gravity near the ground)
  Damping,  ///< a = -v / tau: relaxes a state to equilibrium (the polytrope's set-up)
};
/// Self-gravity between all particles (seed 003 eq. 2.3; softened, eq. 2.43).
enum class GravityType {
  None,
  Direct,  ///< O(N^2) direct summation, a gather over every other particle in storage order
  Tree,    ///< Barnes-Hut tree, monopole + quadrupole (seed 003 App. A): O(N log N)
  Fmm,     ///< fast multipole method, cell-cell expansions to order gravity.fmm_order (gravity/fmm.h)
};
/// The finite pointset method (seed 002): moving least squares on the particles instead of kernel sums.
enum class FpmType {
  None,
  BurgersViscous,  ///< Du/Dt = eps u_xx, Dx/Dt = u (seed 002 eqs. 6a-6b, 16-17)
  BurgersUpwind,   ///< Du/Dt = -u u_x / 2 by one-sided MLS, Dx/Dt = u / 2 (seed 002 eqs. 18-21)
};
/// Wall particles (kind Wall) built by the scene; periodic and mirror boundaries of the domain are ghosts.
enum class WallType {
  None,
  LennardJones,  ///< a repulsive central force from wall particles within r0 (seed 001 eq. 60)
  Dummy,         ///< wall particles in the sums, pressure extrapolated from the fluid (Adami et al. 2012)
};

/// The slots, in pipeline order (the GUI lists them in this order).
enum class Slot { Density, Smoothing, Eos, Force, Viscosity, Xsph, Conduction, Energy, BodyForce, Gravity, Walls, Fpm, Count };
inline constexpr std::size_t kSlotCount = static_cast<std::size_t>(Slot::Count);

struct Physics {
  DensityMode density = DensityMode::Summation;
  HMode smoothing = HMode::Variable;
  EosType eos = EosType::IdealGas;
  ForceType force = ForceType::Standard;
  ViscType viscosity = ViscType::Monaghan;
  Toggle xsph = Toggle::Off;        ///< XSPH drift velocity v* (seed 001 eqs. 45-47)
  Toggle conduction = Toggle::Off;  ///< artificial thermal conductivity (Price 2008, JCP 227, 10040)
  Toggle energy = Toggle::On;       ///< internal energy equation du/dt (seed 000 eq. 3.3.19)
  BodyForce body_force = BodyForce::None;
  GravityType gravity = GravityType::None;
  WallType walls = WallType::None;
  FpmType fpm = FpmType::None;
  /// visc.switch: a parameter of the viscosity slot rather than a slot (it changes the stages).
  ViscSwitch visc_switch = ViscSwitch::None;

  bool corrected() const { return force == ForceType::Corrected || force == ForceType::StandardCorrected; }
  bool operator==(const Physics&) const = default;

  /// The chosen option of a slot, by name ("summation", "none", ...), and setting it by name.
  std::string get(Slot s) const;
  bool set(Slot s, std::string_view option);
  /// Empty if the combination makes sense; otherwise one message naming both slots involved.
  std::string validate() const;

 private:
  std::string validate_dfsph() const;  ///< the slots the incompressible solver needs (eos = dfsph)
};

/// Key (without "physics."), description and option names of a slot, in declaration order.
struct SlotInfo {
  Slot slot;
  std::string_view key;          ///< e.g. "density": the parameter key is physics.density
  std::string_view description;  ///< one line with the seed equations
  std::vector<std::string> options;
  bool live;                     ///< may change while a scene runs (false: needs a reset)
};
const std::array<SlotInfo, kSlotCount>& slot_table();
const SlotInfo& slot_info(Slot s);

}  // namespace sph

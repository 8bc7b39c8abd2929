// Slot names, options and the combinations that make no sense (see sph/physics.h).
#include "sph/physics.h"
#include "sph/params.h"

#include <stdexcept>
#include <type_traits>

namespace sph {
namespace {

template <class E>
struct Names {
  std::vector<std::pair<std::string, E>> list;
  std::string name(E e) const {
    for (const auto& [n, v] : list)
      if (v == e) return n;
    return "?";
  }
  bool parse(std::string_view s, E& out) const {
    for (const auto& [n, v] : list)
      if (s == n) { out = v; return true; }
    return false;
  }
  std::vector<std::string> options() const {
    std::vector<std::string> o;
    for (const auto& [n, v] : list) o.push_back(n);
    return o;
  }
};

const Names<DensityMode> kDensity{{{"none", DensityMode::None}, {"summation", DensityMode::Summation},
                                   {"continuity", DensityMode::Continuity}, {"volume", DensityMode::Volume}}};
const Names<HMode> kSmoothing{{{"variable", HMode::Variable}, {"fixed", HMode::Fixed}, {"evolved", HMode::Evolved}}};
const Names<EosType> kEos{{{"none", EosType::None}, {"ideal_gas", EosType::IdealGas}, {"tait", EosType::Tait},
                           {"isothermal", EosType::Isothermal}, {"polytropic", EosType::Polytropic},
                           {"dfsph", EosType::Dfsph}}};
const Names<ForceType> kForce{{{"none", ForceType::None}, {"standard", ForceType::Standard},
                               {"corrected", ForceType::Corrected}, {"standard_corrected", ForceType::StandardCorrected}}};
const Names<ViscType> kVisc{{{"none", ViscType::None}, {"monaghan", ViscType::Monaghan}, {"laplacian", ViscType::Laplacian}}};
const Names<Toggle> kToggle{{{"none", Toggle::Off}, {"on", Toggle::On}}};
const Names<BodyForce> kBody{{{"none", BodyForce::None}, {"uniform", BodyForce::Uniform}, {"damping", BodyForce::Damping}}};
const Names<GravityType> kGravity{{{"none", GravityType::None}, {"direct", GravityType::Direct}, {"tree", GravityType::Tree}, {"fmm", GravityType::Fmm}}};
const Names<WallType> kWalls{{{"none", WallType::None}, {"lennard_jones", WallType::LennardJones}, {"dummy", WallType::Dummy}}};

const Names<FpmType> kFpm{{{"none", FpmType::None}, {"burgers_viscous", FpmType::BurgersViscous},
                           {"burgers_upwind", FpmType::BurgersUpwind}}};

bool parse_toggle(std::string_view s, Toggle& t) {
  if (s == "off") { t = Toggle::Off; return true; }  // accepted as a synonym of none
  return kToggle.parse(s, t);
}

/// Calls f(names, member) with the option names of slot s and the member of ph that holds its choice;
/// false for Slot::Count. (PhysicsT: Physics or const Physics.)
template <class PhysicsT, class F>
bool with_slot(PhysicsT& ph, Slot s, F&& f) {
  switch (s) {
    case Slot::Density: f(kDensity, ph.density); return true;
    case Slot::Smoothing: f(kSmoothing, ph.smoothing); return true;
    case Slot::Eos: f(kEos, ph.eos); return true;
    case Slot::Force: f(kForce, ph.force); return true;
    case Slot::Viscosity: f(kVisc, ph.viscosity); return true;
    case Slot::Xsph: f(kToggle, ph.xsph); return true;
    case Slot::Conduction: f(kToggle, ph.conduction); return true;
    case Slot::Energy: f(kToggle, ph.energy); return true;
    case Slot::BodyForce: f(kBody, ph.body_force); return true;
    case Slot::Gravity: f(kGravity, ph.gravity); return true;
    case Slot::Walls: f(kWalls, ph.walls); return true;
    case Slot::Fpm: f(kFpm, ph.fpm); return true;
    case Slot::Count: break;
  }
  return false;
}

}  // namespace

const std::array<SlotInfo, kSlotCount>& slot_table() {
  static const std::array<SlotInfo, kSlotCount> table{{
      {Slot::Density, "density",
       "how rho is obtained: summation (seed 000 eq. 3.2.17), continuity (seed 001 eq. 39), volume 1/V = sum W (seed 004)",
       kDensity.options(), false},
      {Slot::Smoothing, "smoothing",
       "smoothing length: variable by Newton-Raphson with grad-h terms (seed 000 eq. 3.5.1), fixed, or evolved from the "
       "continuity density",
       kSmoothing.options(), true},
      {Slot::Eos, "eos",
       "equation of state: ideal gas (seed 000 eq. 3.3.23), Tait/Cole (seed 001 eq. 3), isothermal, polytropic P = K rho^gamma "
       "(seed 003 eq. 3.72), or dfsph: an incompressible liquid whose pressure is solved for (Bender & Koschier 2017)",
       kEos.options(), false},
      {Slot::Force, "force",
       "momentum equation: standard (seed 001 eq. 44), corrected (eqs. 48-52), standard-corrected (eqs. 53-55)",
       kForce.options(), true},
      {Slot::Viscosity, "viscosity",
       "Monaghan artificial viscosity Pi (seed 003 eq. 3.16) or a physical Laplacian viscosity from first derivatives "
       "(seed 004)",
       kVisc.options(), true},
      {Slot::Xsph, "xsph", "XSPH: particles move with a smoothed velocity v* (seed 001 eqs. 45-47)", kToggle.options(), true},
      {Slot::Conduction, "conduction", "artificial thermal conductivity (Price 2008) in the energy equation",
       kToggle.options(), true},
      {Slot::Energy, "energy", "internal energy equation du/dt (seed 000 eq. 3.3.19)", kToggle.options(), false},
      {Slot::BodyForce, "body_force", "external body force: uniform gravity g, or a damping a = -v/tau that relaxes a state",
       kBody.options(), true},
      {Slot::Gravity, "gravity",
       "self-gravity: direct summation O(N^2), a Barnes-Hut tree O(N log N) (seed 003 eq. 2.43, App. A) or the fast "
       "multipole method O(N) (Dehnen 2002)",
       kGravity.options(), true},
      {Slot::Walls, "walls",
       "wall particles: Lennard-Jones repulsion (seed 001 eq. 60) or dummy particles with extrapolated pressure "
       "(Adami et al. 2012)",
       kWalls.options(), false},
      {Slot::Fpm, "fpm",
       "finite pointset method (seed 002): Burgers' equation by moving least squares, viscous (eqs. 16-17) or upwind "
       "(eqs. 18-21)",
       kFpm.options(), false},
  }};
  return table;
}

const SlotInfo& slot_info(Slot s) { return slot_table()[static_cast<std::size_t>(s)]; }

std::string Physics::get(Slot s) const {
  std::string name;
  if (with_slot(*this, s, [&](const auto& names, const auto& value) { name = names.name(value); })) return name;
  throw std::logic_error("Physics::get: no such slot");
}

bool Physics::set(Slot s, std::string_view o) {
  bool ok = false;
  with_slot(*this, s, [&](const auto& names, auto& value) {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(value)>, Toggle>) ok = parse_toggle(o, value);
    else ok = names.parse(o, value);
  });
  return ok;
}

std::string Physics::validate() const {
  auto is = [&](Slot s) { return "physics." + std::string(slot_info(s).key) + " = " + get(s); };
  if (fpm != FpmType::None)  // a method of its own: no kernel sums, no EOS, no other forces
    for (Slot s : {Slot::Density, Slot::Eos, Slot::Force, Slot::Viscosity, Slot::Xsph, Slot::Energy, Slot::BodyForce,
                   Slot::Gravity, Slot::Walls})
      if (get(s) != "none") return is(Slot::Fpm) + " is a method of its own, but " + is(s) + " (set it to none)";
  if (force != ForceType::None && density == DensityMode::None)
    return is(Slot::Force) + " needs densities, but " + is(Slot::Density);
  if (force != ForceType::None && eos == EosType::None)
    return is(Slot::Force) + " needs pressures, but " + is(Slot::Eos);
  if (eos != EosType::None && density == DensityMode::None)
    return is(Slot::Eos) + " needs densities, but " + is(Slot::Density);
  if (smoothing == HMode::Variable && density != DensityMode::Summation && density != DensityMode::Volume)
    return is(Slot::Smoothing) + " solves h together with a summed density, but " + is(Slot::Density) +
           " (choose fixed or evolved)";
  if (smoothing == HMode::Evolved && density != DensityMode::Continuity)
    return is(Slot::Smoothing) + " follows the evolved density, but " + is(Slot::Density) + " (it needs continuity)";
  if (energy == Toggle::On && eos != EosType::IdealGas)
    return is(Slot::Energy) + " evolves u for the ideal gas, but " + is(Slot::Eos) + " does not depend on u";
  if (energy == Toggle::On && force != ForceType::Standard)
    return is(Slot::Energy) + " is the energy equation of the standard grad-h form (seed 000 eq. 3.3.19), but " +
           is(Slot::Force);
  if (viscosity != ViscType::None && force == ForceType::None)
    return is(Slot::Viscosity) + " acts through the momentum equation, but " + is(Slot::Force);
  if (visc_switch != ViscSwitch::None && viscosity != ViscType::Monaghan)
    return std::string("visc.switch = ") + to_string(visc_switch) + " sets the alpha of the Monaghan viscosity, but " +
           is(Slot::Viscosity);
  if (visc_switch != ViscSwitch::None && force != ForceType::Standard && force != ForceType::StandardCorrected)
    return std::string("visc.switch = ") + to_string(visc_switch) +
           " acts in the standard and standard-corrected pair loops, but " + is(Slot::Force);
  if (xsph == Toggle::On && density == DensityMode::None)
    return is(Slot::Xsph) + " averages with densities, but " + is(Slot::Density);
  if (conduction == Toggle::On && energy == Toggle::Off)
    return is(Slot::Conduction) + " conducts internal energy, but " + is(Slot::Energy);
  if (corrected() && smoothing == HMode::Variable)
    return is(Slot::Force) + " has no grad-h terms, but " + is(Slot::Smoothing) + " (choose fixed or evolved)";
  if (walls == WallType::Dummy && eos != EosType::Tait && eos != EosType::Dfsph)
    return is(Slot::Walls) + " inverts the Tait equation for the wall density, but " + is(Slot::Eos);
  if (eos == EosType::Dfsph) return validate_dfsph();
  if (walls == WallType::Dummy && force == ForceType::None)
    return is(Slot::Walls) + " acts through the pressure force, but " + is(Slot::Force);
  return {};
}

std::string Physics::validate_dfsph() const {
  auto is = [&](Slot s) { return "physics." + std::string(slot_info(s).key) + " = " + get(s); };
  const std::string d = is(Slot::Eos) + " ";
  if (density != DensityMode::Summation) return d + "solves for the summation density, but " + is(Slot::Density);
  if (smoothing != HMode::Fixed) return d + "keeps h fixed, but " + is(Slot::Smoothing);
  if (force != ForceType::Standard) return d + "adds its pressure to the standard form's other forces, but " + is(Slot::Force);
  if (viscosity == ViscType::Monaghan)
    return d + "has no sound speed for the Monaghan viscosity, but " + is(Slot::Viscosity) + " (choose laplacian or none)";
  if (xsph == Toggle::On) return d + "moves particles with v, but " + is(Slot::Xsph);
  if (walls == WallType::LennardJones) return d + "needs walls in its sums, but " + is(Slot::Walls) + " (choose dummy)";
  if (gravity != GravityType::None) return d + "is a liquid solver, but " + is(Slot::Gravity);
  return {};
}

}  // namespace sph

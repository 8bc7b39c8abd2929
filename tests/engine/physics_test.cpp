// The physics slots (sph/physics.h, params/physics.cpp): combinations that make no sense are refused with
// one message naming both slots and their options, every built-in scene's default physics is a valid
// combination its scene accepts, and every option of every slot round-trips through set/get by name.
#include "sph/physics.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "sph/config.h"
#include "sph/scene.h"

namespace sph {
namespace {

/// A weakly compressible liquid (seed 001): valid.
Physics liquid() {
  Physics ph;
  ph.density = DensityMode::Continuity;
  ph.smoothing = HMode::Fixed;
  ph.eos = EosType::Tait;
  ph.force = ForceType::Standard;
  ph.viscosity = ViscType::Monaghan;
  ph.energy = Toggle::Off;
  return ph;
}

/// The same without viscosity (so that removing the force breaks only what the case is about).
Physics inviscid_liquid() {
  Physics ph = liquid();
  ph.viscosity = ViscType::None;
  return ph;
}

/// The default: an ideal gas with summation density, variable h and the energy equation (seed 000).
Physics gas() { return Physics{}; }

/// The gas without the energy equation (a barotropic gas): valid.
Physics barotropic_gas() {
  Physics ph;
  ph.energy = Toggle::Off;
  return ph;
}

/// Nothing at all: valid (no stage runs).
Physics nothing() {
  Physics ph;
  ph.density = DensityMode::None;
  ph.smoothing = HMode::Fixed;
  ph.eos = EosType::None;
  ph.force = ForceType::None;
  ph.viscosity = ViscType::None;
  ph.energy = Toggle::Off;
  return ph;
}

/// A valid base and two slot choices that together make no sense (the base may already have one of them).
struct Bad {
  const char* what;
  Physics base;
  Slot s1;
  const char* o1;
  Slot s2;
  const char* o2;
};

const Bad kBad[] = {
    {"force without density", liquid(), Slot::Force, "standard", Slot::Density, "none"},
    {"force without pressure", liquid(), Slot::Force, "standard", Slot::Eos, "none"},
    {"EOS without density", nothing(), Slot::Eos, "tait", Slot::Density, "none"},
    {"energy with Tait", liquid(), Slot::Energy, "on", Slot::Eos, "tait"},
    {"energy with a corrected force", gas(), Slot::Energy, "on", Slot::Force, "corrected"},
    {"continuity with variable h", liquid(), Slot::Density, "continuity", Slot::Smoothing, "variable"},
    {"evolved h with summation", gas(), Slot::Smoothing, "evolved", Slot::Density, "summation"},
    {"viscosity without force", nothing(), Slot::Viscosity, "monaghan", Slot::Force, "none"},
    {"XSPH without density", nothing(), Slot::Xsph, "on", Slot::Density, "none"},
    {"conduction without energy", liquid(), Slot::Conduction, "on", Slot::Energy, "none"},
    {"corrected force with variable h", barotropic_gas(), Slot::Force, "standard_corrected", Slot::Smoothing, "variable"},
    {"dummy walls without Tait", gas(), Slot::Walls, "dummy", Slot::Eos, "ideal_gas"},
    {"dummy walls without force", inviscid_liquid(), Slot::Walls, "dummy", Slot::Force, "none"},
};

std::string named(Slot s, const std::string& option) {
  return "physics." + std::string(slot_info(s).key) + " = " + option;
}

TEST(Physics, NonsenseCombinationsNameBothSlots) {
  for (const Bad& b : kBad) {
    EXPECT_EQ(b.base.validate(), "") << b.what << ": the base must be valid, so the pair is to blame";
    Physics ph = b.base;
    ASSERT_TRUE(ph.set(b.s1, b.o1)) << b.what;
    ASSERT_TRUE(ph.set(b.s2, b.o2)) << b.what;
    const std::string msg = ph.validate();
    EXPECT_NE(msg.find(named(b.s1, b.o1)), std::string::npos) << b.what << ": " << msg;
    EXPECT_NE(msg.find(named(b.s2, b.o2)), std::string::npos) << b.what << ": " << msg;
  }
}

TEST(Physics, EveryRegisteredSceneDefaultsToAValidCombination) {
  ASSERT_FALSE(scene_registry().empty());
  for (const SceneSpec& s : scene_registry()) {
    const RunConfig cfg = RunConfig::from_scene(s.name);
    EXPECT_EQ(cfg.params.physics.validate(), "") << s.name;
    EXPECT_NO_THROW(check_physics(s, cfg.params.physics)) << s.name << ": its defaults are options it allows";
    EXPECT_NO_THROW(cfg.validate()) << s.name;
  }
}

TEST(Physics, EveryOptionOfEverySlotRoundTrips) {
  for (const SlotInfo& info : slot_table()) {
    ASSERT_FALSE(info.options.empty()) << info.key;
    EXPECT_EQ(&slot_info(info.slot), &info);
    std::set<std::string> seen;
    for (const std::string& option : info.options) {
      EXPECT_TRUE(seen.insert(option).second) << info.key << ": duplicate option " << option;
      Physics ph;
      const Physics before = ph;
      ASSERT_TRUE(ph.set(info.slot, option)) << info.key << " = " << option;
      EXPECT_EQ(ph.get(info.slot), option);
      for (const SlotInfo& other : slot_table())  // no other slot changed
        if (other.slot != info.slot) {
          EXPECT_EQ(ph.get(other.slot), before.get(other.slot)) << info.key << " = " << option;
        }
    }
    Physics ph;
    const Physics before = ph;
    EXPECT_FALSE(ph.set(info.slot, "no_such_option")) << info.key;
    EXPECT_TRUE(ph == before) << info.key << ": a refused option changes nothing";
  }
  // "off" is accepted for the toggles and reads back as their canonical "none"
  Physics ph;
  ph.xsph = Toggle::On;
  EXPECT_TRUE(ph.set(Slot::Xsph, "off"));
  EXPECT_EQ(ph.get(Slot::Xsph), "none");
}

}  // namespace
}  // namespace sph

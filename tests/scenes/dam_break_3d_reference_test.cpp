// SPHERIC test 2's sensor P1 (reference/dam_break_3d_reference.h) on still water in front of the box:
// fluid and dummy-wall particles on a lattice carry the hydrostatic pressure rho g (D - z) (the walls
// theirs extrapolated, as Adami's are), and the sensor on the box's face at z = 0.021 m reads it. A
// layer of water two spacings deep must wet the sensor: the sensor of the last stop (the fluid alone,
// dry below a third of a full kernel) read 0 under it, and so read the impact 0.08 s late.
#include "reference/dam_break_3d_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "sph/vec.h"

namespace sph::scenes {
namespace {

constexpr double kFace = 0.8245, kRho = 1000.0, kG = 9.81, kDx = 0.02;

/// Water of depth D [m] in front of the face (x > face) on a floor (z > 0), three wall layers behind the
/// face and under the floor; P = rho g (D - z) everywhere.
Particles still_water(double D) {
  std::vector<Vec3> pts;
  std::vector<std::uint8_t> wall;
  for (int k = -3; (k + 0.5) * kDx < D; ++k)
    for (int j = 0; j < 30; ++j)
      for (int i = -3; i < 15; ++i) {
        pts.push_back({kFace + (i + 0.5) * kDx, 0.171 + (j + 0.5) * kDx, (k + 0.5) * kDx});
        wall.push_back(i < 0 || k < 0 ? 1 : 0);
      }
  Particles p(3, pts.size(), FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::Pressure).add(Field::H));
  for (std::size_t a = 0; a < pts.size(); ++a) {
    p.x[0][a] = pts[a].x;
    p.x[1][a] = pts[a].y;
    p.x[2][a] = pts[a].z;
    p.kind[a] = wall[a];
    p[Field::Mass][a] = kRho * kDx * kDx * kDx;
    p[Field::Density][a] = kRho;
    p[Field::Pressure][a] = kRho * kG * (D - pts[a].z);
    p[Field::H][a] = 1.3 * kDx;
  }
  p.partition_by_kind();
  return p;
}

double p1(double D) {
  const auto ref = make_dam_break_3d_reference({kDx, kDx, kDx}, 0.55, kFace);
  return ref->evaluate(still_water(D), 0.0)[static_cast<std::size_t>(find_column(ref->columns(), "P1"))];
}

TEST(DamBreak3dReference, P1ReadsTheHydrostaticPressureOnTheFace) {
  const double read = p1(0.3), want = kRho * kG * (0.3 - 0.021);
  std::printf("P1 under 0.3 m of still water: %.1f Pa, rho g (D - z) = %.1f Pa\n", read, want);
  EXPECT_NEAR(read, want, 0.01 * want);  // a linear field, a kernel full of fluid and walls
}

TEST(DamBreak3dReference, AThinLayerWetsTheSensor) {
  const double read = p1(2 * kDx), want = kRho * kG * (2 * kDx - 0.021);
  std::printf("P1 under 2 dx = %.2f m of water: %.1f Pa (rho g (D - z) = %.1f Pa)\n", 2 * kDx, read, want);
  // wet, and near the hydrostatic value: measured +13%, the kernel cut by the surface above the sensor
  // weighs the deeper (higher) pressures more
  EXPECT_NEAR(read, want, 0.25 * want);
}

}  // namespace
}  // namespace sph::scenes

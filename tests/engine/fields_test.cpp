// Per-particle fields (sph/fields.h, core/particles.cpp, neighbours/ghosts.cpp): a FieldSet holds any
// number of the kFieldCount (> 32) fields; Particles allocates added fields zero-filled at the full size
// (ghosts included); and ghost copies transform vectors and tensors as a mirror does: under a reflection
// M of axis k, a vector becomes M v and a velocity gradient M G M, so component (k, l) changes sign when
// exactly one of k and l is the mirrored axis, and a corner image (two mirrors) flips nothing twice.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "sph/domain.h"
#include "sph/fields.h"
#include "sph/particles.h"

namespace sph {
namespace {

FieldSet every_field() {
  FieldSet s;
  for (std::size_t i = 0; i < kFieldCount; ++i) s.add(static_cast<Field>(i));
  return s;
}

TEST(Fields, FieldSetHoldsEveryField) {
  static_assert(kFieldCount > 32, "the point of this test: more members than a 32-bit mask holds");
  const FieldSet all = every_field();
  EXPECT_EQ(all.count(), kFieldCount);
  EXPECT_FALSE(all.empty());
  for (std::size_t i = 0; i < kFieldCount; ++i) EXPECT_TRUE(all.has(static_cast<Field>(i)));
  std::vector<std::size_t> order;
  all.for_each([&](Field f) { order.push_back(index(f)); });
  ASSERT_EQ(order.size(), kFieldCount);
  for (std::size_t i = 0; i < kFieldCount; ++i) EXPECT_EQ(order[i], i);  // enum order
  EXPECT_TRUE(FieldSet{}.empty());
  EXPECT_EQ(FieldSet{}.count(), 0u);
}

TEST(Fields, ListedSetsAndLeadingComponents) {
  EXPECT_TRUE((FieldSet{Field::Density, Field::Energy}) == FieldSet{}.add(Field::Density).add(Field::Energy));
  const FieldSet planar = FieldSet{}.add_vector(Field::XsphX, 2).add_tensor(Field::VelGradXX, 2);
  EXPECT_TRUE(planar == (FieldSet{Field::XsphX, Field::XsphY, Field::VelGradXX, Field::VelGradXY,
                                  Field::VelGradYX, Field::VelGradYY}));
  EXPECT_TRUE(FieldSet{}.add_tensor(Field::CorrXX, 1) == FieldSet{Field::CorrXX});
}

TEST(Fields, SetAlgebraAcrossTheThirtyTwoBitBoundary) {
  const FieldSet low = FieldSet{}.add(Field::Mass).add(Field::Density);
  const FieldSet high = FieldSet{}.add_tensor(Field::VelGradXX);  // indices 29..37
  EXPECT_GT(index(Field::VelGradZZ), 32u);
  EXPECT_EQ(high.count(), 9u);
  const FieldSet u = low | high;
  EXPECT_EQ(u.count(), 11u);
  EXPECT_TRUE(u.has(Field::Mass));
  EXPECT_TRUE(u.has(Field::VelGradZZ));
  EXPECT_FALSE(u.has(Field::XsphX));
  EXPECT_TRUE((u & low) == low);
  EXPECT_TRUE((low & high).empty());
  FieldSet w = low;
  w |= high;
  EXPECT_TRUE(w == u);
  EXPECT_EQ(FieldSet{}.add_vector(Field::XsphX).count(), 3u);
  EXPECT_TRUE(FieldSet{}.add_vector(Field::XsphX).has(Field::XsphZ));
  EXPECT_EQ(component(Field::VelGradXX, 2, 1), Field::VelGradZY);  // row by row
  EXPECT_EQ(component(Field::CorrCX, 1), Field::CorrCY);
  std::size_t visited = 0;
  std::size_t last = 0;
  u.for_each([&](Field f) {
    if (visited++ > 0) {
      EXPECT_GT(index(f), last);
    }
    last = index(f);
  });
  EXPECT_EQ(visited, 11u);
}

TEST(Fields, AddFieldsAllocatesZeroFilledAtTheTotalSize) {
  Particles p(2, 4, FieldSet{}.add(Field::Mass));
  p.resize_total(7);  // 4 real + 3 ghosts
  EXPECT_THROW(p[Field::VelGradZZ], std::logic_error);
  p[Field::Mass].assign(7, 2.0);
  p.add_fields(FieldSet{}.add(Field::VelGradZZ).add(Field::Mass));
  EXPECT_TRUE(p.has(Field::VelGradZZ));
  ASSERT_EQ(p[Field::VelGradZZ].size(), p.total());
  for (double v : p[Field::VelGradZZ]) EXPECT_EQ(v, 0.0);
  for (double v : p[Field::Mass]) EXPECT_EQ(v, 2.0);  // an allocated field is left alone
  p.resize_total(9);  // later resizes keep it in step
  EXPECT_EQ(p[Field::VelGradZZ].size(), 9u);
}

/// One particle near the corner (0, 0) of a box with mirror walls on x and y: its x, y and corner images.
Particles corner_particle() {
  Particles p(2, 1, FieldSet{}.add(Field::Density).add_vector(Field::XsphX).add_tensor(Field::VelGradXX));
  p.x[0][0] = 0.05;
  p.x[1][0] = 0.03;
  p.v[0][0] = 1.5;
  p.v[1][0] = -2.5;
  Domain d;
  d.bc = {Boundary::Wall, Boundary::Wall, Boundary::Open};
  make_ghosts(d, 0.1, p);
  return p;
}

TEST(Fields, GhostVectorsFlipTheirNormalComponent) {
  Particles p = corner_particle();
  ASSERT_EQ(p.ghost_src.size(), 3u);  // x image, y image, corner image
  p[Field::Density][0] = 1000.0;
  p[Field::XsphX][0] = 0.25;
  p[Field::XsphY][0] = -0.75;
  copy_ghost_field(p, Field::Density);
  copy_ghost_field(p, Field::XsphX);
  copy_ghost_field(p, Field::XsphY);
  copy_ghost_velocity(p);
  for (std::size_t g = 0; g < 3; ++g) {
    const std::size_t i = 1 + g;
    const unsigned flip = p.ghost_flip[g];
    const double sx = flip & 1u ? -1.0 : 1.0, sy = flip & 2u ? -1.0 : 1.0;  // M = diag(sx, sy)
    EXPECT_EQ(p.x[0][i], sx > 0 ? 0.05 : -0.05);  // mirrored position 2 lo - x
    EXPECT_EQ(p.x[1][i], sy > 0 ? 0.03 : -0.03);
    EXPECT_EQ(p[Field::Density][i], 1000.0);  // scalars are copied unchanged
    EXPECT_EQ(p[Field::XsphX][i], sx * 0.25);  // M v
    EXPECT_EQ(p[Field::XsphY][i], sy * -0.75);
    EXPECT_EQ(p.v[0][i], sx * 1.5);  // the velocity transforms the same way
    EXPECT_EQ(p.v[1][i], sy * -2.5);
  }
  // every combination of mirrors appears once
  EXPECT_EQ(p.ghost_flip[0] | p.ghost_flip[1] | p.ghost_flip[2], 3u);
  EXPECT_NE(p.ghost_flip[0], p.ghost_flip[1]);
  EXPECT_NE(p.ghost_flip[1], p.ghost_flip[2]);
}

TEST(Fields, GhostTensorsTransformAsMGM) {
  Particles p = corner_particle();
  const double G[3][3] = {{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, {7.0, 8.0, 9.0}};  // dv_k/dx_l
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) p[component(Field::VelGradXX, k, l)][0] = G[k][l];
  copy_ghost_fields(p, FieldSet{}.add_tensor(Field::VelGradXX));
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    const unsigned flip = p.ghost_flip[g];
    const double M[3] = {flip & 1u ? -1.0 : 1.0, flip & 2u ? -1.0 : 1.0, flip & 4u ? -1.0 : 1.0};
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        EXPECT_EQ(p[component(Field::VelGradXX, k, l)][1 + g], M[k] * G[k][l] * M[l])
            << "flip " << flip << " component " << k << l;
  }
  // concretely: one mirror flips the off-diagonal xy and yx, never the diagonal; the corner flips neither
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    const std::size_t i = 1 + g;
    EXPECT_EQ(p[Field::VelGradXX][i], 1.0);
    EXPECT_EQ(p[Field::VelGradYY][i], 5.0);
    const double expected_xy = p.ghost_flip[g] == 3u ? 2.0 : -2.0;
    EXPECT_EQ(p[Field::VelGradXY][i], expected_xy);
  }
}

TEST(Fields, FlipAxesOfEveryFieldMatchItsTensorRank) {
  // Scalars never flip; vector component k flips under axis k; tensor (k, l) under k xor l.
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(info(component(Field::XsphX, k)).flip_axes, 1u << k);
    EXPECT_EQ(info(component(Field::CorrCX, k)).flip_axes, 1u << k);
    for (int l = 0; l < 3; ++l) {
      const unsigned expected = (1u << k) ^ (1u << l);
      EXPECT_EQ(info(component(Field::VelGradXX, k, l)).flip_axes, expected);
      EXPECT_EQ(info(component(Field::CorrXX, k, l)).flip_axes, expected);
    }
  }
  for (Field f : {Field::Mass, Field::Density, Field::H, Field::Pressure, Field::Energy, Field::Shepard,
                  Field::DensityRate, Field::SoundSpeed})
    EXPECT_EQ(info(f).flip_axes, 0u) << info(f).key;
}

}  // namespace
}  // namespace sph

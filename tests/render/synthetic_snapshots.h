// Hand-built snapshots for the renderer tests and benchmark (no engine library involved).
#pragma once
#include <cstddef>
#include <string>

#include "sph/snapshot.h"

namespace sph::render::test {

/// nx x ny particles on the cell centres of [0,2]x[0,1]; fields "rho" = 1 + x (range [1,3] over the
/// domain) and "p" = y; h = 1.2 dx.
Snapshot lattice_2d(int nx, int ny);
/// Value of "rho" at lattice_2d's particle (i, j) and its index in the arrays.
std::size_t lattice_index(int nx, int i, int j);

/// lattice_2d whose bottom row and first and last columns are walls (kind 1); their "rho" and "p" are
/// kWallValue, far outside the fluid's ranges, which min/max cover (as the engine's do).
Snapshot tank_2d(int nx, int ny);
inline constexpr float kWallValue = 1000.f;

/// A closed polyline of n + 1 vertices around the circle (cx, cy, r) in world units.
Outline circle_outline(std::string label, float cx, float cy, float r, int n);

/// Sod shock tube at t = 0.2 on [-0.5, 0.5]: n particles whose "rho" and "p" follow the exact solution
/// slightly smoothed, plus the exact curves of both sampled at 801 points.
Snapshot sod_profile_1d(int n);
/// sod_profile_1d with its density 20% low on (0, 0.15), where the exact curve is flat: a run B that differs.
Snapshot sod_profile_1d_run_b(int n);
/// The exact Sod density at t = 0.2 (gamma = 1.4, left rho = p = 1, right rho = 0.125, p = 0.1).
float sod_exact_rho(float x);

/// n particles filling a ball of radius 1 centred in [-1,1]^3, denser towards the centre; "rho" and "u".
Snapshot ball_3d(int n);

/// n particles at deterministic pseudo-random positions in the unit square (dim 2) or cube (dim 3),
/// one field "rho"; h chosen for about 30 (2D) / 60 (3D) neighbours.
Snapshot random_cloud(int dim, int n);

}  // namespace sph::render::test

// The difference map of an A/B comparison in 2D and 3D: at each fluid particle of run A, run B's value
// of the field at the nearest fluid particle of B minus A's own value (nearest-particle interpolation
// of B onto A's particles: no smoothing, so a shock displaced by one spacing shows as one band of
// particles). Walls and non-finite values give NaN.
#pragma once
#include <span>
#include <vector>

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// One value per particle of a (NaN where undefined): vb at the nearest fluid particle of b minus va.
/// va and vb hold one value per particle of a and of b.
std::vector<float> nearest_difference(const sph::Snapshot& a, std::span<const float> va, const sph::Snapshot& b,
                                      std::span<const float> vb);

}  // namespace sph::render

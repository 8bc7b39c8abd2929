// The inspector's marks on the particle view, and picking: a ring around the picked particle and the reach
// of its kernel, fainter rings around its neighbours (their opacity and width grow with their kernel weight), wherever the
// frame draws that run's particles (the plane, every profile panel); and which drawn particle is
// nearest to a pixel.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "frame_build.h"
#include "frame_scene.h"

namespace sph::render {

/// Adds the rings of `h` to f.over (the primary particles belong to run 0), and the picked particle's kernel
/// support: a circle (plane and 3D views) or, in a profile, the interval x +- R along the plotted axis.
void add_highlight(FrameBuild& f, const Highlight& h, bool profile);

/// The particle drawn nearest to frame pixel (px, py), if one is within max_px of it.
std::optional<Picked> pick_particle(const FrameBuild& f, float px, float py, float max_px);

/// Where particle `index` of `run` is drawn (the first plot showing it) [frame px]; nullopt if nowhere.
std::optional<std::array<float, 2>> locate_particle(const FrameBuild& f, int run, std::uint32_t index);

}  // namespace sph::render

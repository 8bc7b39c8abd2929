// The inspector's marks on the particle view, and picking: a ring around the picked particle, fainter
// rings around its neighbours (their opacity and width grow with their kernel weight), wherever the
// frame draws that run's particles (the plane, every profile panel); and which drawn particle is
// nearest to a pixel.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "frame_build.h"
#include "frame_scene.h"

namespace sph::render {

/// Adds the rings of `h` to f.over (the primary particles belong to run 0).
void add_highlight(FrameBuild& f, const Highlight& h);

/// The particle drawn nearest to frame pixel (px, py), if one is within max_px of it.
std::optional<Picked> pick_particle(const FrameBuild& f, float px, float py, float max_px);

/// Where particle `index` of `run` is drawn (the first plot showing it) [frame px]; nullopt if nowhere.
std::optional<std::array<float, 2>> locate_particle(const FrameBuild& f, int run, std::uint32_t index);

}  // namespace sph::render

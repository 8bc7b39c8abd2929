// GLSL sources of shaders/, embedded into the binary at build time (see CMakeLists.txt), so that
// programs run from any directory.
#pragma once
#include <string_view>

namespace sph::render {

/// The text of shaders/<file_name> ("particles.vert"), or an empty view if there is no such file.
std::string_view shader_source(std::string_view file_name);

}  // namespace sph::render

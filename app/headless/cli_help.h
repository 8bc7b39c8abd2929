// `sph help [SCENE]` and `sph params`: the text of sph/help_text.h on the terminal (the GUI's help
// window shows the same text).
#pragma once
#include <string>
#include <vector>

namespace sph::cli {

/// Without a scene: the scenes, one line each. With one (a name, a scene file or an HDF5 IC, and
/// --set overrides): its description, stages, parameters, values and reference.
int help_command(const std::string& scene, const std::vector<std::string>& sets);
int params_command();

}  // namespace sph::cli

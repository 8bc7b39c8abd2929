// The text that explains a scene and its parameters: `sph help SCENE`, `sph params` and the GUI's help
// window all print what these functions return (one source, so the command line and the window agree).
#pragma once
#include <string>

#include "sph/config.h"

namespace sph {

/// A scene as it runs with `cfg`: its description, dimension and units; the stage of every physics slot
/// (with the options the scene accepts and the seed equations); every parameter of those stages (key,
/// value, unit, range, the scene's default, meaning with its seed equation, whether it needs a reset); the
/// scene's own values; its reference and its error norms. Lines of at most about 100 columns.
std::string scene_help(const RunConfig& cfg);

/// Every run parameter key, grouped by stage: unit, range or choices, the default of a gas scene, and the
/// stage that uses it (a key is accepted only by scenes that run that stage).
std::string params_help();

/// The built-in scenes, one line each (name, dimension, category): what `sph help` without a scene prints.
std::string scenes_help();

}  // namespace sph

// The module's parts, each binding its share of the World class (module.cpp calls them in turn).
#pragma once
#include <pybind11/pybind11.h>

#include "py_world.h"

namespace sph::py {

using WorldClass = pybind11::class_<PyWorld>;

/// Particle fields as NumPy arrays: views over the engine's storage (py_fields.cpp).
void bind_fields(WorldClass& cls);
/// Diagnostics, the reference's values and the run's warnings as dicts (py_report.cpp).
void bind_report(WorldClass& cls);
/// A frame of the shared renderer as an RGBA NumPy image (py_render.cpp).
void bind_render(WorldClass& cls);

}  // namespace sph::py

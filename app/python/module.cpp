// The Python module sphsandbox: the engine's worlds from Python (README "Python"). Scenes by name or file
// with `sph run --set`-style overrides, stepping, fields as NumPy views, diagnostics and reference errors,
// frames of the shared renderer, checkpoints. The engine's errors arrive as Python exceptions carrying its
// message: ConfigError (a ValueError), DivergedError and CheckpointError.
#include <omp.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "py_bindings.h"
#include "sph/checkpoint.h"
#include "sph/diverged.h"
#include "sph/key_value.h"
#include "sph/scene.h"

namespace sph::py {
namespace {

namespace pyb = pybind11;
using Overrides = std::vector<std::pair<std::string, std::string>>;

/// A value as the command line would spell it: True -> "true", 0.1 -> "0.1" (Python's shortest repr).
std::string spelled(const pyb::handle& v) {
  if (pyb::isinstance<pyb::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (pyb::isinstance<pyb::float_>(v)) return pyb::repr(v).cast<std::string>();
  return pyb::str(v).cast<std::string>();
}

/// set= as a dict {key: value} or a list of "key=value" strings (in order), or None.
Overrides overrides(const pyb::object& set) {
  Overrides out;
  if (set.is_none()) return out;
  if (pyb::isinstance<pyb::dict>(set)) {
    for (auto [k, v] : set.cast<pyb::dict>()) out.emplace_back(pyb::str(k).cast<std::string>(), spelled(v));
    return out;
  }
  if (pyb::isinstance<pyb::str>(set)) throw ConfigError("set: expected a dict or a list of \"key=value\" strings, not one string");
  for (const pyb::handle item : set) {
    const std::string text = pyb::str(item).cast<std::string>();
    const auto kv = split_key_value(text);
    if (!kv) throw ConfigError("set " + text + ": expected key=value");
    out.emplace_back(kv->key, kv->value);
  }
  return out;
}

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const SceneSpec& s : scene_registry()) names.push_back(s.name);
  return names;
}

}  // namespace
}  // namespace sph::py

PYBIND11_MODULE(sphsandbox, m) {
  namespace pyb = pybind11;
  using namespace sph::py;
  m.doc() = "The SPH sandbox's engine from Python: worlds of its scenes, stepped, read as NumPy arrays, rendered.";
  pyb::register_exception<sph::ConfigError>(m, "ConfigError", PyExc_ValueError);
  pyb::register_exception<sph::DivergedError>(m, "DivergedError", PyExc_RuntimeError);
  pyb::register_exception<sph::CheckpointError>(m, "CheckpointError", PyExc_OSError);
  m.def("scenes", &scene_names, "The built-in scenes' names (sph list).");
  m.def("set_threads", [](int n) {
    if (n < 1) throw sph::ConfigError("set_threads: expected at least 1 thread");
    omp_set_num_threads(n);
  }, pyb::arg("n"), "OpenMP threads of later steps (results are the same for any count).");

  WorldClass cls(m, "World", "A scene's world: its particles, pipeline of stages, integrator and reference.");
  cls.def(pyb::init([](const std::string& scene, const pyb::object& set) {
            return std::make_unique<PyWorld>(scene, overrides(set));
          }),
          pyb::arg("scene"), pyb::arg("set") = pyb::none(),
          "World('sod', set={'kernel.type': 'M6', 'scene.n': 200}): a built-in scene, a JSON scene file or an HDF5\n"
          "initial condition, with overrides as `sph run --set` takes them. ConfigError names a bad key or value.");
  cls.def_static("load_state", &PyWorld::load_state, pyb::arg("path"),
                 "A world continuing a checkpoint (save_state's, or `sph run --checkpoint-every`'s checkpoint.sph).");
  cls.def("save_state", &PyWorld::save_state, pyb::arg("path"), "Writes the whole state (the checkpoint format).");
  cls.def("step", &PyWorld::step, pyb::arg("dt_max") = 1e300, pyb::call_guard<pyb::gil_scoped_release>(),
          "One step of the scene's time step, shortened to at most dt_max.");
  cls.def("run_to", &PyWorld::run_to, pyb::arg("t"), pyb::call_guard<pyb::gil_scoped_release>(),
          "Steps until time t (the last step lands on t), then checks the state as sph run does before an output.");
  cls.def("set_params", [](PyWorld& w, const pyb::object& set) { w.set_params(overrides(set)); }, pyb::arg("set"),
          "Run-parameter overrides from the next step on (as the GUI's live edits); scene.* keys need a new World.");
  cls.def_property_readonly("generation", &PyWorld::generation,
                            "Changes whenever the world does (step, run_to, set_params): field() views taken before are stale.");
  bind_fields(cls);
  bind_report(cls);
  bind_render(cls);
  cls.def("__repr__", [](const PyWorld& w) {
    return "<sphsandbox.World " + w.world().config().scene->name + " t=" + std::to_string(w.world().time()) + " n=" +
           std::to_string(w.world().particles().size()) + ">";
  });
}

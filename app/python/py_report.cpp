// What the world reports, as Python values: the conserved quantities of diagnostics.csv, the reference's
// columns of errors.csv (errors and measurements, with their validity) and the warnings of warnings.csv.
#include <pybind11/stl.h>

#include "py_bindings.h"
#include "sph/diagnostics.h"
#include "sph/report.h"

namespace sph::py {
namespace {

namespace pyb = pybind11;

pyb::dict diagnostics(const PyWorld& w) {
  const Diagnostics d = w.world().report().diagnostics();
  pyb::dict r;
  r["step"] = d.step;
  r["t"] = d.t;
  r["dt"] = d.dt;
  r["E_kin"] = d.E_kin;
  r["E_int"] = d.E_int;
  r["E_pot"] = d.E_pot;
  r["E_tot"] = d.E_tot;
  r["P"] = pyb::make_tuple(d.P[0], d.P[1], d.P[2]);
  r["L"] = pyb::make_tuple(d.L[0], d.L[1], d.L[2]);
  r["v_max"] = d.v_max;
  r["h_iter_mean"] = d.h_iter_mean;
  r["h_iter_max"] = d.h_iter_max;
  r["neighbours_mean"] = d.neighbours_mean;
  r["updates"] = d.updates;
  r["dfsph_iter"] = d.dfsph_iter;  // DFSPH's solves of the last step (0 without)
  r["dfsph_div_iter"] = d.dfsph_div_iter;
  r["dfsph_error"] = d.dfsph_error;
  r["dfsph_error_max"] = d.dfsph_error_max;
  return r;
}

/// The reference's columns now by name, and "valid": whether the reference applies at this time.
pyb::dict errors(const PyWorld& w) {
  const Report rep = w.world().report();
  pyb::dict r;
  if (!rep.has_reference()) return r;
  const std::vector<double> values = rep.reference_values();
  const auto& cols = rep.reference_columns();
  for (std::size_t c = 0; c < cols.size(); ++c) r[pyb::str(cols[c].name)] = values[c];
  r["valid"] = w.world().time() <= rep.reference()->valid_until();
  return r;
}

pyb::list warnings(const PyWorld& w) {
  pyb::list out;
  for (const RunWarning& x : w.world().checks().warnings()) {
    pyb::dict d;
    d["kind"] = x.kind;
    d["message"] = x.message;
    d["step"] = x.step;
    d["t"] = x.t;
    d["particle"] = x.particle;
    d["times"] = x.times;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_report(WorldClass& cls) {
  cls.def("diagnostics", &diagnostics, "The conserved quantities of diagnostics.csv now, as a dict.");
  cls.def("errors", &errors,
          "The reference's columns of errors.csv now (error norms and measurements) and 'valid'; {} without a reference.");
  cls.def("warnings", &warnings, "What the run has tolerated so far (warnings.csv): kind, message, step, t, particle, times.");
  cls.def_property_readonly("time", [](const PyWorld& w) { return w.world().time(); }, "Simulated time.");
  cls.def_property_readonly("steps", [](const PyWorld& w) { return w.world().steps(); }, "Steps taken.");
  cls.def_property_readonly("dim", [](const PyWorld& w) { return w.world().particles().dim(); }, "Dimension 1, 2 or 3.");
  cls.def_property_readonly("n", [](const PyWorld& w) { return w.world().particles().size(); },
                            "Real particles (fluid and walls): the length of every field.");
  cls.def_property_readonly("n_fluid", [](const PyWorld& w) { return w.world().particles().fluid(); },
                            "Fluid particles: the first n_fluid entries of every field.");
  cls.def_property_readonly("scene", [](const PyWorld& w) { return w.world().config().scene->name; }, "The scene's name.");
  cls.def_property_readonly("t_end", [](const PyWorld& w) { return w.world().params().time.t_end; }, "The scene's end time.");
  cls.def("config_json", [](const PyWorld& w) { return w.world().config().to_json(); },
          "Every parameter as resolved, as the JSON text of a scene file (sph run takes it).");
}

}  // namespace sph::py

// Text rows of diagnostics.csv and errors.csv (full double precision).
#include <cstdio>

#include "sph/diagnostics.h"
#include "text/number_text.h"

namespace sph {
namespace {

std::string fmt(double v) { return short_text(v); }

/// Appends ",value" (written out to avoid a GCC 12 -Wrestrict false positive on "," + string).
void field(std::string& s, const std::string& v) {
  s.push_back(',');
  s.append(v);
}

}  // namespace

std::string diagnostics_csv_header() {
  return "step,t,dt,E_kin,E_int,E_pot,E_tot,px,py,pz,Lx,Ly,Lz,v_max,h_iter_mean,h_iter_max,h_not_converged,"
         "neighbours_mean,correction_fallbacks,updates,dfsph_iter,dfsph_div_iter,dfsph_error,dfsph_error_max";
}

std::string diagnostics_csv_row(const Diagnostics& d) {
  std::string s = std::to_string(d.step);
  for (double v : {d.t, d.dt, d.E_kin, d.E_int, d.E_pot, d.E_tot, d.P[0], d.P[1], d.P[2], d.L[0], d.L[1], d.L[2],
                   d.v_max, d.h_iter_mean})
    field(s, fmt(v));
  field(s, std::to_string(d.h_iter_max));
  field(s, std::to_string(d.h_not_converged));
  field(s, fmt(d.neighbours_mean));
  field(s, std::to_string(d.correction_fallbacks));
  field(s, std::to_string(d.updates));
  field(s, std::to_string(d.dfsph_iter));
  field(s, std::to_string(d.dfsph_div_iter));
  field(s, fmt(d.dfsph_error));
  field(s, fmt(d.dfsph_error_max));
  return s;
}

std::string errors_csv_header(const std::vector<RefColumn>& columns) {
  std::string s = "t";
  for (const auto& c : columns) field(s, c.name);
  field(s, "valid");
  return s;
}

std::string errors_csv_row(double t, const std::vector<double>& values, bool valid) {
  std::string s = fmt(t);
  for (double v : values) field(s, fmt(v));
  field(s, valid ? "1" : "0");
  return s;
}

}  // namespace sph

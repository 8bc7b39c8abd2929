// Conserved quantities and error norms reported at every output (seed 000 eqs. 3.4.1–3.4.5).
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace sph {

struct Diagnostics {
  std::int64_t step = 0;
  double t = 0.0, dt = 0.0;
  double E_kin = 0.0;  ///< sum 1/2 m v^2
  double E_int = 0.0;  ///< sum m u
  double E_pot = 0.0;  ///< gravitational potential energy (0 without gravity)
  double E_tot = 0.0;  ///< E_kin + E_int + E_pot
  std::array<double, 3> P{0, 0, 0};  ///< linear momentum sum m v
  std::array<double, 3> L{0, 0, 0};  ///< angular momentum sum r x m v about the origin
  double v_max = 0.0;                ///< max |v|
  double h_iter_mean = 0.0;          ///< mean Newton-Raphson iterations of the last density solve
  int h_iter_max = 0;
  std::size_t h_not_converged = 0;
  double neighbours_mean = 0.0;
};

/// L1 = mean over particles in the scene's window of |f - f_exact| (and the max norm).
struct ErrorNorms {
  double t = 0.0;
  std::size_t count = 0;  ///< particles inside the window
  double L1_rho = 0.0, L1_v = 0.0, L1_p = 0.0, L1_u = 0.0;
  double Linf_rho = 0.0;
};

/// CSV header line and row for diagnostics.csv.
std::string diagnostics_csv_header();
std::string diagnostics_csv_row(const Diagnostics& d);
std::string errors_csv_header();
std::string errors_csv_row(const ErrorNorms& e);

}  // namespace sph

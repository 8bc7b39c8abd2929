// Conserved quantities reported at every step (seed 000 eqs. 3.4.1–3.4.5), and the text rows of
// diagnostics.csv and errors.csv.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sph/reference.h"

namespace sph {

struct Diagnostics {
  std::int64_t step = 0;
  double t = 0.0, dt = 0.0;
  double E_kin = 0.0;  ///< sum 1/2 m v^2 over the fluid
  double E_int = 0.0;  ///< internal energy of the EOS: sum m u (gas), sum m e(rho) (Tait)
  double E_pot = 0.0;  ///< potential energy of the body force and the Lennard-Jones walls (0 without)
  double E_tot = 0.0;  ///< E_kin + E_int + E_pot
  std::array<double, 3> P{0, 0, 0};  ///< linear momentum sum m v
  std::array<double, 3> L{0, 0, 0};  ///< angular momentum sum r x m v about the origin
  double v_max = 0.0;                ///< max |v|
  double h_iter_mean = 0.0;          ///< mean Newton-Raphson iterations of the last density solve
  int h_iter_max = 0;
  std::size_t h_not_converged = 0;
  double neighbours_mean = 0.0;
  std::size_t correction_fallbacks = 0;  ///< particles whose gradient correction fell back to L = I
  std::int64_t updates = 0;  ///< particle evaluations so far: with individual time steps, the active ones
  // DFSPH (physics.eos = dfsph; 0 otherwise), of the last step:
  int dfsph_iter = 0;            ///< iterations of the constant-density solve
  int dfsph_div_iter = 0;        ///< iterations of the divergence-free solve
  double dfsph_error = 0.0;      ///< mean density error after the solve (ProjectionStats::density_error) [dimensionless]
  double dfsph_error_max = 0.0;  ///< the worst particle's [dimensionless]
};

/// CSV header line and row for diagnostics.csv.
std::string diagnostics_csv_header();
std::string diagnostics_csv_row(const Diagnostics& d);
/// errors.csv: "t," then the reference's column names, then "valid"; a row is t, the values, and 1 while
/// the reference applies (t <= Reference::valid_until()), else 0.
std::string errors_csv_header(const std::vector<RefColumn>& columns);
std::string errors_csv_row(double t, const std::vector<double>& values, bool valid);

}  // namespace sph

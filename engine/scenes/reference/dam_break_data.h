// Measured surge-front positions of the collapse of a water column of width a and height 2a:
// Z/a against T = t sqrt(2 g / a).
//  - Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312-324, Fig. 3 (n^2 = 2, a = 1.125 in);
//  - Koshizuka & Oka (1996), Nucl. Sci. Eng. 123, 421-434 (their experiment, a = 0.146 m).
// The values as read from the figures and tabulated in PySPH's db_exp_data.py; the same T scaling is
// used for both sets there.
#pragma once
#include <span>
#include <utility>

namespace sph::scenes {

std::span<const std::pair<double, double>> martin_moyce_front();
std::span<const std::pair<double, double>> koshizuka_oka_front();

/// Linear interpolation of Z/a at T; NaN outside the data's range.
double interpolate_front(std::span<const std::pair<double, double>> data, double T);

}  // namespace sph::scenes

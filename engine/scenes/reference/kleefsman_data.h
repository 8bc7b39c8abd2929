// The MARIN measurements of SPHERIC benchmark test 2 (Kleefsman et al. 2005, J. Comput. Phys. 206, 363;
// the test case of Issa & Violeau 2006, https://www.spheric-sph.org/tests/test-02): water heights at
// gauges H2 (x = 0.992 m) and H4 (x = 2.638 m), and the pressure at sensor P1 on the box's front face.
// The archived series (sampled every 1.007 ms) resampled linearly: the heights every 10 ms over [0, 1.99] s,
// P1 every 1 ms over [0.3, 1.0] s, the first impact. (The series end at 1.99 s here.)
#pragma once

namespace sph::scenes {

double kleefsman_h2(double t);  ///< [m]; NaN outside [0, kleefsman_end()]
double kleefsman_h4(double t);  ///< [m]; NaN outside [0, kleefsman_end()]
double kleefsman_p1(double t);  ///< [Pa]; NaN outside [0.3, 1.0] s
double kleefsman_end();         ///< the end of the height series [s]

}  // namespace sph::scenes

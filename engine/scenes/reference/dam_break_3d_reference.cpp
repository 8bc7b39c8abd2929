// The gauges of SPHERIC test 2 (Kleefsman et al. 2005; Issa & Violeau 2006) read from the particles:
//  - a water height H at (x, 0.5): the fluid volume above the floor per unit area, sum_i V_i w(|r_i - x|)
//    over the particles' horizontal distances with a normalised 2D cubic spline w of smoothing length
//    2 dx (support 4 dx): a lattice column of height h gives h, splashes count as the volume they carry;
//  - the pressure P1 at (face, 0.471, 0.021), on the box's face as the sensor is: the Shepard average
//    sum_i V_i P_i W / sum_i V_i W with the M4 spline of the particles' h over the fluid and the wall
//    particles, which carry the pressure extrapolated from the fluid (Adami's dummy walls; DFSPH's too);
//    0 while the fluid holds less than a tenth of the kernel's volume (the sensor is dry). Until this
//    stop the sum took the fluid alone, one spacing into the water, and called the sensor dry below a
//    third: the floor and the box take more than half of that kernel, so the sensor stayed dry until
//    the water had piled up about 8 cm deep, some 0.08 s after the front's tongue reached the box.
// The measured series are MARIN's (kleefsman_data.h); the heights' error is |H - H_exp| / depth.
#include "dam_break_3d_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kleefsman_data.h"
#include "sph/kernel.h"

namespace sph::scenes {
namespace {

constexpr double kGaugeX[4] = {0.496, 0.992, 1.488, 2.638}, kGaugeY = 0.5;  // H1-H4 [m]
constexpr double kP1y = 0.471, kP1z = 0.021;                                 // P1 on the box's face [m]

class DamBreak3dReference final : public Reference {
 public:
  DamBreak3dReference(std::array<double, 3> a, double depth, double face)
      : a_(a), depth_(depth), face_(face), plane_(KernelType::M4, 2), space_(KernelType::M4, 3) {}

  std::vector<RefColumn> columns() const override {
    return {{"H1", "water height at gauge H1 (x = 0.496 m) [m]", false},
            {"H2", "water height at gauge H2 (x = 0.992 m) [m]", false},
            {"H3", "water height at gauge H3 (x = 1.488 m) [m]", false},
            {"H4", "water height at gauge H4 (x = 2.638 m, in the column) [m]", false},
            {"H2_exp", "H2 measured (MARIN; nan after the series' end) [m]", false},
            {"H4_exp", "H4 measured [m]", false},
            {"P1", "pressure at sensor P1 on the box's front face (z = 0.021 m) [Pa]", false},
            {"P1_exp", "P1 measured [Pa]", false},
            {"P1_peak", "largest P1 of the evaluations so far [Pa]", false},
            {"P1_peak_t", "time of P1_peak [s]", false},
            {"err_H2", "|H2 - H2_exp| / initial depth", true},
            {"err_H4", "|H4 - H4_exp| / initial depth", true},
            {"err_H", "the larger of err_H2 and err_H4", true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    std::array<double, 4> Hg{};
    const double hg = 2.0 * std::max(a_[0], a_[1]);
    double psum = 0.0, wsum = 0.0, wet = 0.0;
    const double* m = p[Field::Mass].data();
    const double* rho = p[Field::Density].data();
    const double* P = p[Field::Pressure].data();
    const double* h = p[Field::H].data();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double V = m[i] / rho[i], x = p.x[0][i], y = p.x[1][i], z = p.x[2][i];
      const double w = V * space_.W(std::sqrt((x - face_) * (x - face_) + (y - kP1y) * (y - kP1y) +
                                              (z - kP1z) * (z - kP1z)), h[i]);
      psum += w * P[i];
      wsum += w;
      if (i >= p.fluid()) continue;
      wet += w;
      for (int g = 0; g < 4; ++g) Hg[g] += V * plane_.W(std::hypot(x - kGaugeX[g], y - kGaugeY), hg);
    }
    const double P1 = wet > 0.1 ? psum / wsum : 0.0;
    if (P1 > peak_) { peak_ = P1; peak_t_ = t; }
    const double h2 = kleefsman_h2(t), h4 = kleefsman_h4(t);
    const double e2 = std::abs(Hg[1] - h2) / depth_, e4 = std::abs(Hg[3] - h4) / depth_;
    const double e = std::isnan(e2) ? e4 : std::isnan(e4) ? e2 : std::max(e2, e4);
    return {Hg[0], Hg[1], Hg[2], Hg[3], h2, h4, P1, kleefsman_p1(t), peak_, peak_t_, e2, e4, e};
  }

  std::string description() const override {
    return "SPHERIC test 2 (Kleefsman et al. 2005): water heights at gauges H1-H4 (fluid volume per area under a "
           "2D spline of 2 dx) and pressure at P1 (Shepard average of fluid and walls on the box's face) against the MARIN "
           "measurements; err_H = |H - H_exp| / 0.55 m for H2 and H4";
  }
  int primary() const override { return 12; }
  std::vector<std::pair<int, int>> series() const override { return {{1, 4}, {3, 5}, {6, 7}}; }
  double valid_until() const override { return kleefsman_end(); }
  std::string valid_until_reason() const override { return "the measured series kept here end"; }
  std::vector<double> saved_state() const override { return {peak_, peak_t_}; }
  bool restore_state(const std::vector<double>& s) override {
    if (s.size() != 2) return false;
    peak_ = s[0];
    peak_t_ = s[1];
    return true;
  }

 private:
  std::array<double, 3> a_;
  double depth_, face_;
  Kernel plane_, space_;  ///< the M4 spline in 2D (the gauges' footprint) and 3D (P1's average)
  mutable double peak_ = -std::numeric_limits<double>::infinity(), peak_t_ = 0.0;
};

}  // namespace

std::unique_ptr<Reference> make_dam_break_3d_reference(std::array<double, 3> spacing, double depth, double box_face) {
  return std::make_unique<DamBreak3dReference>(spacing, depth, box_face);
}

}  // namespace sph::scenes

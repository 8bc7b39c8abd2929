// The exact curves of a radial flow (the Sedov blast, the Noh implosion): density, speed and pressure
// against the distance r from the origin (axis 3), filled point by point where the reference samples them.
#pragma once
#include <utility>

#include "sph/reference.h"

namespace sph::scenes {

struct RadialCurves {
  ExactCurve rho{"rho", {}, {}, 3}, speed{"speed", {}, {}, 3}, P{"p", {}, {}, 3};

  /// The point r with the exact density, speed and pressure there.
  void add(double r, double rho_r, double speed_r, double P_r) {
    for (ExactCurve* e : {&rho, &speed, &P}) e->x.push_back(static_cast<float>(r));
    rho.value.push_back(static_cast<float>(rho_r));
    speed.value.push_back(static_cast<float>(speed_r));
    P.value.push_back(static_cast<float>(P_r));
  }

  /// The three curves as profiles: rho, speed, p.
  ReferenceCurves take() {
    ReferenceCurves c;
    c.profiles = {std::move(rho), std::move(speed), std::move(P)};
    return c;
  }
};

}  // namespace sph::scenes

#include "drop_ode.h"

#include <algorithm>
#include <cmath>

namespace sph::scenes {
namespace {

DropState rate(const DropState& s) {
  const double a4 = s.a * s.a * s.a * s.a;
  return {s.A * s.A * (a4 - 1.0) / (a4 + 1.0), -s.a * s.A};
}

DropState axpy(const DropState& y, double c, const DropState& k) { return {y.A + c * k.A, y.a + c * k.a}; }

}  // namespace

DropState drop_ode(double A0, double t) {
  DropState y{A0, 1.0};
  if (!(t > 0.0) || A0 == 0.0) return y;
  const double h_max = 1e-7 * 100.0 / std::abs(A0);
  const int steps = static_cast<int>(std::ceil(t / h_max));
  const double h = t / steps;
  for (int s = 0; s < steps; ++s) {
    const DropState k1 = rate(y), k2 = rate(axpy(y, 0.5 * h, k1)), k3 = rate(axpy(y, 0.5 * h, k2)),
                    k4 = rate(axpy(y, h, k3));
    y.A += h / 6.0 * (k1.A + 2.0 * k2.A + 2.0 * k3.A + k4.A);
    y.a += h / 6.0 * (k1.a + 2.0 * k2.a + 2.0 * k3.a + k4.a);
  }
  return y;
}

}  // namespace sph::scenes

// Runtime choice of the integrator (Params::integrator).
#include "sph/integrator.h"

namespace sph {

std::unique_ptr<Integrator> make_predictor_corrector();
std::unique_ptr<Integrator> make_euler();
std::unique_ptr<Integrator> make_rk4();
std::unique_ptr<Integrator> make_leapfrog();

std::unique_ptr<Integrator> make_integrator(IntegratorType type) {
  switch (type) {
    case IntegratorType::Euler: return make_euler();
    case IntegratorType::RK4: return make_rk4();
    case IntegratorType::Leapfrog: return make_leapfrog();
    case IntegratorType::PredictorCorrector: return make_predictor_corrector();
  }
  return make_leapfrog();
}

}  // namespace sph

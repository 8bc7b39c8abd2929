// DivergedError's messages: which particle, field, step and time, or the reason a check gave.
#include "sph/diverged.h"

namespace sph {

DivergedError::DivergedError(std::int64_t particle_, std::int64_t step_, double t_, const std::string& field_)
    : std::runtime_error(particle_ >= 0 ? "simulation diverged: particle " + std::to_string(particle_) +
                                              " has a non-finite " + field_ + " at step " + std::to_string(step_) +
                                              " (t = " + std::to_string(t_) + ")"
                                        : "simulation diverged: " + field_ + " at step " + std::to_string(step_) +
                                              " (t = " + std::to_string(t_) + ")"),
      particle(particle_), step(step_), t(t_), field(field_) {}

DivergedError::DivergedError(std::int64_t particle_, std::int64_t step_, double t_, const std::string& field_,
                             const std::string& reason)
    : std::runtime_error("simulation diverged: " + reason + " at step " + std::to_string(step_) +
                         " (t = " + std::to_string(t_) + ")"),
      particle(particle_), step(step_), t(t_), field(field_) {}

}  // namespace sph

// How idle OpenMP threads wait (issue 14). GCC's runtime lets a thread that reaches a barrier spin for
// a while before it sleeps. On a two-core machine whose other core is busy (the GUI's render thread, a
// compiler), the spinning thread loses its core and every barrier then waits for the scheduler: a
// 20k-particle step measured here took 0.30 s with spinning threads against 0.013 s with sleeping ones
// (and 0.018 s on one thread). The runtime reads OMP_WAIT_POLICY once, when it loads, so a program that
// wants sleeping threads by default sets the variable and starts itself again; a value the user set is
// kept.
#pragma once
#include <cstdlib>

#include <unistd.h>

namespace sph {

/// Call first in main(): unless OMP_WAIT_POLICY is set, set it to passive and re-execute this program
/// with the same arguments (on failure it carries on with the runtime's default).
inline void prefer_sleeping_threads(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

/// The wait policy this process runs with ("passive", "active", or "default").
inline const char* thread_wait_policy() {
  const char* p = std::getenv("OMP_WAIT_POLICY");
  return p ? p : "default";
}

}  // namespace sph

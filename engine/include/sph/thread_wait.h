// How idle OpenMP threads wait (thread_limit_bench and scaling_bench, tests/bench/README.md). GCC's
// runtime lets a thread that reaches a barrier spin (300,000 turns by default) before it sleeps. On a
// two-core machine whose other core is busy (the GUI's render thread, a compiler) the spinning thread
// loses its core and every barrier then waits for the scheduler: a 20k-particle step measured here took
// 0.30 s with spinning threads against 0.013 s with sleeping ones (and 0.018 s on one thread). Sleeping
// at once (OMP_WAIT_POLICY=passive) costs a wake-up at every parallel loop instead: on the idle machine
// box_random ran 1.42-1.61x faster on two threads than on one when they slept, 1.74-2.08x when they spun
// 20,000 turns first, and beside a busy core the short spin did as well as sleeping (0.91-1.29x; the
// team chooser then keeps one thread). The runtime reads its variables once, when it loads, so a program
// that wants the short spin by default sets GOMP_SPINCOUNT and starts itself again; a policy or spin
// count the user set is kept.
#pragma once
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace sph {

/// Turns an idle thread spins at a barrier before it sleeps, unless the user chose (see above).
inline constexpr const char* kSpinTurns = "20000";

/// Call first in main(): unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is set, set GOMP_SPINCOUNT to
/// kSpinTurns and re-execute this program with the same arguments (on failure it carries on with the
/// runtime's default).
inline void prefer_brief_spinning(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("GOMP_SPINCOUNT", kSpinTurns, 1) != 0) return;
  execv("/proc/self/exe", argv);
}

/// How idle threads of this process wait: "passive", "active", "spin N turns, then sleep" or "default".
inline std::string thread_wait_policy() {
  if (const char* p = std::getenv("OMP_WAIT_POLICY")) return p;
  if (const char* n = std::getenv("GOMP_SPINCOUNT")) return std::string("spin ") + n + " turns, then sleep";
  return "default";
}

}  // namespace sph

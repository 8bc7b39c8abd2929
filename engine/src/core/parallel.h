// When loops over particles use a thread team. Below kParallelMin particles a team costs more than it
// saves, and on a loaded machine (GUI thread, ctest -j2) every barrier can wait a whole scheduler slice
// for a descheduled thread: measured 1.1 s on one thread against 45 s on two for the 1600-particle tube
// with another process running. Results do not depend on this choice (gather loops, fixed order).
#pragma once
#include <cstddef>

namespace sph {

inline constexpr std::size_t kParallelMin = 4096;

}  // namespace sph

// When loops over particles use a thread team. Below kParallelMin particles a team costs more than it
// saves, and on a loaded machine (GUI thread, ctest -j2) every barrier can wait a whole scheduler slice
// for a descheduled thread: measured 1.1 s on one thread against 45 s on two for the 1600-particle tube
// with another process running. Results do not depend on this choice (gather loops, fixed order).
//
// The pair loops over particles (density, forces, corrections, XSPH) use schedule(static): every loop
// gives a thread the same contiguous block of the Morton-ordered particles, so the data a thread wrote
// in one loop (h, rho, P, ...) are still in its own core's cache when the next loop reads them, and the
// two threads share only the lines at their blocks' edge. With dynamic chunks of 64 particles each loop
// dealt the particles out anew, and about half of what a thread read had been written on the other
// core. Measured on box_random with two threads against one (scaling_bench, three alternations, 40 steps):
// 1.75-1.82x at 20k, 1.45-1.89x at 80k, 1.93-2.05x at 160k against 1.40-1.56x, 1.49-1.68x and
// 1.65-1.86x with dynamic chunks. A neighbour count that SPH keeps near constant makes equal blocks
// equal work; loops whose cost per particle varies widely (the gravity tree, walls) stay dynamic.
#pragma once
#include <cstddef>

namespace sph {

inline constexpr std::size_t kParallelMin = 4096;

}  // namespace sph

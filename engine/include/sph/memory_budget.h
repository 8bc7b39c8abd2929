// Memory a run would need, checked before anything is allocated: an enormous particle count (or frame)
// is refused up front with the memory it would take, instead of failing halfway (or being killed).
#pragma once
#include <string>

#include "sph/config.h"

namespace sph {

/// Particles the scene will place, estimated from its count parameters: an n_side is n_side^dim lattice
/// sites (x 1.2 for a close packing), another count is taken as is (x 2 when it counts "per" body, as
/// "particles per star"); 0 when the scene has no count parameter (few-body scenes, HDF5 files).
double estimated_particles(const RunConfig& cfg);
/// Memory a run of `particles` needs [bytes], neighbour lists included: 1 KiB a particle in 1D and 2D,
/// 2.5 KiB in 3D (measured peak RSS: sedov 184k particles 175 MB, polytrope 100k 256 MB).
double run_memory_bytes(double particles, int dim);
/// Memory this process can still take [bytes]: the smaller of the system's MemAvailable and the
/// address-space limit (ulimit -v) less what is already mapped; +inf when neither is known.
double available_memory_bytes();
/// "12.3 GiB" / "512 MiB".
std::string memory_text(double bytes);
/// Throws ConfigError naming the count key, the particles and the memory when the run would need more
/// than available_memory_bytes().
void check_run_memory(const RunConfig& cfg);

}  // namespace sph

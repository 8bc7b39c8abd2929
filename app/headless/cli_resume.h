// sph resume DIR: continue a run from DIR/checkpoint.sph with the options it was started with.
#pragma once
#include <string>

namespace sph::cli {

/// threads > 0 overrides the run's thread count (results do not depend on it).
/// until >= 0 moves the end time (a run can go on beyond the end it had).
/// quiet: no summary line, whatever the run had.
int resume_command(const std::string& dir, int threads, double until, bool quiet);

}  // namespace sph::cli

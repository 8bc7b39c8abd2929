// SIGINT and SIGTERM during `sph run`: the first asks the run loop to stop after the current step (it
// writes a checkpoint and exits 130 or 143); a second one ends the process at once, removing the
// checkpoint's temporary file if one is being written (only complete files are left).
#pragma once

namespace sph::cli {

/// Installs the handlers (once per process).
void install_stop_handlers();
/// 0 while no stop was asked for, else the signal number (SIGINT, SIGTERM).
int stop_signal();
/// The file a second signal removes before exiting (the checkpoint's temporary name); nullptr: none.
/// The string must outlive its registration.
void set_partial_file(const char* path);

}  // namespace sph::cli

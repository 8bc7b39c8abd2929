// Exact leak reports at exit under AddressSanitizer: keeps every shared library loaded so far from being
// unloaded. libglvnd loads Mesa's GL driver with dlopen when the window's context is made and closes it
// at exit, before LeakSanitizer looks: the driver's globals that still point at its blocks are unmapped
// by then, so those blocks (240 B in 3 allocations; Debian 12, Mesa 22.3, Xvfb) were reported as leaked
// from "<unknown module>", which no suppression can match. Pinned, the driver's data stays mapped, the
// blocks are reachable and nothing is reported; no suppression is needed. Does nothing in other builds.
#pragma once

namespace sph::gui {

/// Marks every loaded shared library RTLD_NODELETE (call once the GL context exists); ASan builds only.
void pin_loaded_libraries();

}  // namespace sph::gui

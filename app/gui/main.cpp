// sph-gui: the desktop program. `sph-gui [--scene NAME|FILE] [--set key=value] [--screenshot FILE]
// [--quit-after-frames N] ...`; see gui_options.h.
#include <cstdio>
#include <exception>

#include "gui_app.h"
#include "gui_options.h"
#include "sph/thread_wait.h"

int main(int argc, char** argv) {
  sph::prefer_brief_spinning(argv);  // before any OpenMP use (sph/thread_wait.h)
  sph::gui::GuiOptions options;
  if (const int rc = sph::gui::parse_options(argc, argv, &options); rc >= 0) return rc;
  try {
    return sph::gui::run_gui(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph-gui: internal error: %s\n", e.what());
    return 1;
  }
}

# The main job (README's first command, `cmake --build build --target demo`):
# - with a display (DISPLAY or WAYLAND_DISPLAY set) and the desktop program built: sph-gui on the Sod tube;
# - otherwise: a headless Sod run that prints its error against the exact Riemann solution and renders
#   a PNG sequence through OSMesa, into demo-out/sod/.
set(has_display FALSE)
if(NOT "$ENV{DISPLAY}" STREQUAL "" OR NOT "$ENV{WAYLAND_DISPLAY}" STREQUAL "")
  set(has_display TRUE)
endif()
if(has_display AND EXISTS "${SPH_GUI}")
  include(${CMAKE_CURRENT_LIST_DIR}/gui/demo_gui.cmake)
  return()
endif()
execute_process(COMMAND ${SPH} run --help OUTPUT_VARIABLE help)
set(frames "")
if(help MATCHES "--frames")
  set(frames --frames demo-out/sod/frames --every 0.01 --size 1280x720)
endif()
execute_process(COMMAND ${SPH} run sod --out demo-out/sod ${frames} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sph run sod failed with exit code ${rc}")
endif()
message(STATUS "Output in demo-out/sod: scene.json, diagnostics.csv, particles_*.csv, errors.csv, frames/")

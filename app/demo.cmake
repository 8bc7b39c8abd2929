# The main job (README's first command): a headless Sod run that prints its error against the exact
# solution and writes its files to demo-out/sod. Invoked by the `demo` target.
execute_process(COMMAND ${SPH} run sod --out demo-out/sod RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sph run sod failed with exit code ${rc}")
endif()
message(STATUS "Output in demo-out/sod (scene.json, diagnostics.csv, particles_*.csv, errors.csv)")

# With a display: start the desktop program on the Sod tube (close the window to finish).
message(STATUS "Display found: starting sph-gui --scene sod (close the window to finish)")
execute_process(COMMAND ${SPH_GUI} --scene sod RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(WARNING "sph-gui exited with code ${rc}")
endif()

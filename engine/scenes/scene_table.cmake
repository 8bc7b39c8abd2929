# Generates the table of built-in scenes (builtin_scenes(), scene_registration.h) from the markers
#   SPH_SCENE(ORDER, function)  or  SPH_SCENES(ORDER, function)
# at the start of a line of engine/scenes/*.cpp, sorted by ORDER (a whole number; two scenes may not
# share one). Run as a build step by engine/CMakeLists.txt:
#   cmake -DSCENE_DIR=engine/scenes -DOUT=FILE.cpp -P scene_table.cmake
# The output is rewritten only when it changes, so editing a scene recompiles the table only when a
# marker changed.
file(GLOB scene_files "${SCENE_DIR}/*.cpp")
set(entries "")
foreach(file IN LISTS scene_files)
  get_filename_component(file_name "${file}" NAME)
  file(STRINGS "${file}" markers REGEX "^SPH_SCENES?\\(")
  foreach(marker IN LISTS markers)
    if(NOT marker MATCHES "^SPH_(SCENES?)\\(([0-9]+), *([A-Za-z_][A-Za-z0-9_]*)\\)")
      message(FATAL_ERROR "${file}: malformed scene marker '${marker}': expected SPH_SCENE(ORDER, function) "
                          "or SPH_SCENES(ORDER, function), ORDER a whole number")
    endif()
    list(APPEND entries "${CMAKE_MATCH_2}|${CMAKE_MATCH_1}|${CMAKE_MATCH_3}|${file_name}")
  endforeach()
endforeach()
if(NOT entries)
  message(FATAL_ERROR "no SPH_SCENE marker in ${SCENE_DIR}/*.cpp")
endif()
list(SORT entries COMPARE NATURAL)

set(SPH_SCENE_DECLARATIONS "")
set(SPH_SCENE_CALLS "")
set(previous_order "")
set(previous_where "")
foreach(entry IN LISTS entries)
  string(REPLACE "|" ";" fields "${entry}")
  list(GET fields 0 order)
  list(GET fields 1 kind)
  list(GET fields 2 function)
  list(GET fields 3 where)
  if(order STREQUAL previous_order)
    message(FATAL_ERROR "scene order ${order} is used twice (${previous_where} and ${where}, ${function}): "
                        "each SPH_SCENE marker needs an ORDER of its own")
  endif()
  set(previous_order "${order}")
  set(previous_where "${where}: ${function}")
  string(APPEND SPH_SCENE_DECLARATIONS "SPH_${kind}(${order}, ${function});  // ${where}\n")
  string(APPEND SPH_SCENE_CALLS "  add_scenes(table, ${function}());\n")
endforeach()
configure_file("${CMAKE_CURRENT_LIST_DIR}/scene_table.cpp.in" "${OUT}" @ONLY)

# The C++ copy of shaders/pattern_core.glsl (src/marble/noise/marble_pattern.cpp compiles the
# pattern as C++: one source for CPU and GPU) with one change: two functions' definitions
# are renamed NAME_direct, and NAME -- what the rest of the pattern calls -- is only declared,
# on the same line (line numbers stay the file's). marble_pattern.cpp defines each NAME: the
# function itself, or, inside a batched row, the same arithmetic with what neighbouring points
# share cached (noise/row_memo.inc; bit-identical, tested). The GLSL file itself stays
# self-contained for the GPU and for other engines (shaders/README.md). Re-run at configure
# time when the file changes; a hooked definition that is no longer found stops the build.
set(_core ${CMAKE_SOURCE_DIR}/shaders/pattern_core.glsl)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_core})
file(READ ${_core} _text)
foreach(_hook IN ITEMS "PatCells|pat_voronoi|vec3 p, uint salt" "float|pat_value3|vec3 p, float period, uint seedHash")
  string(REPLACE "|" ";" _parts "${_hook}")
  list(GET _parts 0 _type)
  list(GET _parts 1 _name)
  list(GET _parts 2 _args)
  set(_definition "${_type} ${_name}(${_args}) {")
  string(FIND "${_text}" "${_definition}" _at)
  string(FIND "${_text}" "${_definition}" _last REVERSE)
  if(_at EQUAL -1 OR NOT _at EQUAL _last)
    message(FATAL_ERROR "cmake/PatternCoreCpu.cmake: expected exactly one '${_definition}' in ${_core} "
                        "(the CPU's batched rows hook it; update this list and src/marble/noise/row_memo.inc)")
  endif()
  string(REPLACE "${_definition}" "${_type} ${_name}(${_args}); ${_type} ${_name}_direct(${_args}) {" _text "${_text}")
endforeach()
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/generated/pattern_core_cpu.glsl.inc CONTENT "${_text}")

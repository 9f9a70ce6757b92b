# The C++ copy of shaders/pattern_core.glsl (src/marble/noise/marble_pattern.cpp compiles the
# pattern as C++: one source for CPU and GPU) with one change: three functions' definitions
# are renamed NAME_direct, and NAME -- what the rest of the pattern calls -- is only declared,
# on the same line (line numbers stay the file's). marble_pattern.cpp defines each NAME: the
# function itself, or, inside a batched row, the same arithmetic with what neighbouring points
# share cached (noise/row_memo.inc; bit-identical, tested). The GLSL file itself stays
# self-contained for the GPU and for other engines (shaders/README.md). Re-run at configure
# time when the file changes; a hooked definition that is no longer found stops the build.
set(_core ${CMAKE_SOURCE_DIR}/shaders/pattern_core.glsl)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_core})

# In the variable named TEXT, replaces the one occurrence of FROM by TO; stops the configure
# step, naming WHO hooks it, if FROM is missing or occurs more than once.
function(_pattern_core_replace_once TEXT FROM TO WHO)
  string(FIND "${${TEXT}}" "${FROM}" _at)
  string(FIND "${${TEXT}}" "${FROM}" _last REVERSE)
  if(_at EQUAL -1 OR NOT _at EQUAL _last)
    message(FATAL_ERROR "cmake/PatternCoreCpu.cmake: expected exactly one '${FROM}' in ${_core} (${WHO})")
  endif()
  string(REPLACE "${FROM}" "${TO}" _replaced "${${TEXT}}")
  set(${TEXT} "${_replaced}" PARENT_SCOPE)
endfunction()

file(READ ${_core} _text)
foreach(_hook IN ITEMS "PatCells|pat_voronoi|vec3 p, uint salt" "float|pat_value3|vec3 p, float period, uint seedHash"
                      "float|pat_grain|vec3 p, uint seedHash")
  string(REPLACE "|" ";" _parts "${_hook}")
  list(GET _parts 0 _type)
  list(GET _parts 1 _name)
  list(GET _parts 2 _args)
  _pattern_core_replace_once(_text "${_type} ${_name}(${_args}) {"
                             "${_type} ${_name}(${_args}); ${_type} ${_name}_direct(${_args}) {"
                             "the CPU's batched rows hook it; update this list and src/marble/noise/row_memo.inc")
endforeach()
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/generated/pattern_core_cpu.glsl.inc CONTENT "${_text}")

# The lane copy (src/marble/noise/vein_lanes.inc compiles the pattern a second time with each
# value an 8-point lane: the batched rows' SIMD path). From the copy above, three more changes:
#   * GLSL's `float` is a C++ keyword, so it is spelled `lane_float` (a type vein_lanes.inc
#     defines); uint and vecN are plain names there already. The regex takes whole words only
#     (comments change too, harmlessly), twice because adjacent matches share a delimiter;
#   * the definitions of pat_family_cover, pat_wrap and pat_next are renamed NAME_direct: their
#     early returns or choices depend on the point (a face's fill; a lattice index in range or
#     at the lattice's end), so
#     vein_lanes.inc declares NAME before the file and defines it after, as the same arithmetic
#     with those returns as per-lane selects. Only the name is matched, not the parameters.
set(_lanes "${_text}")
foreach(_pass 1 2)
  string(REGEX REPLACE "([^A-Za-z0-9_])float([^A-Za-z0-9_])" "\\1lane_float\\2" _lanes "${_lanes}")
endforeach()
foreach(_name IN ITEMS pat_family_cover pat_wrap pat_next)
  _pattern_core_replace_once(_lanes "lane_float ${_name}(" "lane_float ${_name}_direct("
                             "'float ${_name}(': the CPU's SIMD rows hook it; update this list and src/marble/noise/vein_lanes.inc")
endforeach()
# GLSL passes the parameter block by value (a copy per call; its lanes are 6 KB here): a const
# reference is the same in C++ for a parameter the pattern never assigns (one that did would stop
# the build).
string(REGEX REPLACE "PatParams P([,)])" "const PatParams& P\\1" _lanes "${_lanes}")
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/generated/pattern_core_lanes.glsl.inc CONTENT "${_lanes}")

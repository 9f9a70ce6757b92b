# CTest `install_example` (cmake -P): installs this build to a fresh prefix, then configures,
# builds and runs examples/embed against the INSTALLED package only -- the way a user's own
# program finds marble (find_package(marble), marble::marble; docs/embedding.md).
# Variables: BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX BUILD_TYPE LAUNCHER SANITIZE
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# The installed package must not point back into the source or build tree.
file(GLOB package_files ${prefix}/lib/cmake/marble/*.cmake)
foreach(f IN LISTS package_files)
  file(READ ${f} text)
  foreach(tree IN ITEMS ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${f} names ${tree}: the installed package depends on the build machine's tree")
    endif()
  endforeach()
endforeach()
foreach(f IN ITEMS include/marble/marble.h lib/libmarble.a bin/marble share/marble/shaders/pattern_core.glsl)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "cmake --install did not write ${f}")
  endif()
endforeach()

set(configure_args -S ${SOURCE_DIR}/examples/embed -B ${WORK_DIR}/build -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
if(LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
if(SANITIZE)  # the library was built with ASan+UBSan: so must the program that links it
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
run("configure the example" ${CMAKE_COMMAND} ${configure_args})
run("build the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run("run the example" ${WORK_DIR}/build/marble_embed_example ${WORK_DIR}/out)
message(STATUS "${last_output}")
foreach(f IN ITEMS render.ppm textures/base_color.png textures/material.json)
  if(NOT EXISTS ${WORK_DIR}/out/${f})
    message(FATAL_ERROR "the example did not write ${f}")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})

# Turns text files (shaders/*.glsl, presets/*.json) into a generated C++ table
# (file name -> text) returned by marble::FUNC(), declared in HEADER, so the binary carries
# them and runs from any folder.
function(marble_embed_files OUTPUT FUNC HEADER)
  set(INPUTS ${ARGN})
  string(REPLACE ";" "|" INPUT_LIST "${INPUTS}")  # a CMake list cannot cross the command line
  add_custom_command(
    OUTPUT ${OUTPUT}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${OUTPUT} -DFUNC=${FUNC} -DHEADER=${HEADER} "-DINPUTS=${INPUT_LIST}"
            -P ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    DEPENDS ${INPUTS} ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    COMMENT "Embedding ${FUNC}"
    VERBATIM)
endfunction()

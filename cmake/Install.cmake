# `cmake --install build [--prefix DIR]` (docs/embedding.md):
#   bin/marble                              the program
#   lib/libmarble.a                         the library (shaders and presets embedded)
#   include/marble/...                      its headers; marble/marble.h is the small public interface
#   lib/cmake/marble/                       the CMake package: find_package(marble), target marble::marble
#   share/marble/shaders/pattern_core.glsl  the pattern for other engines' shaders (shaders/README.md)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS marble RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS marble_lib EXPORT marbleTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/src/marble DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_SOURCE_DIR}/shaders/pattern_core.glsl ${CMAKE_SOURCE_DIR}/shaders/README.md
  DESTINATION ${CMAKE_INSTALL_DATADIR}/marble/shaders)

set(MARBLE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/marble)
install(EXPORT marbleTargets NAMESPACE marble:: DESTINATION ${MARBLE_CMAKE_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/marbleConfig.cmake.in ${CMAKE_BINARY_DIR}/marbleConfig.cmake
  INSTALL_DESTINATION ${MARBLE_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/marbleConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/marbleConfig.cmake ${CMAKE_BINARY_DIR}/marbleConfigVersion.cmake DESTINATION ${MARBLE_CMAKE_DIR})

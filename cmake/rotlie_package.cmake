# The installed CMake package: find_package(rotlie) then rotlie::schemes, rotlie::models (component
# numeric, always) and rotlie::lie, bch, solver, runs, reports (component symbolic, when built).
# The build tree is the same package: rotlieConfig.cmake, its version file and the targets exported
# beside them, so that a consumer also finds a build with -Drotlie_DIR=<build> (or
# CMAKE_PREFIX_PATH=<build>), its headers in the source tree and its libraries where they were built.
include(CMakePackageConfigHelpers)
set(ROTLIE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rotlie)

install(EXPORT rotlie_numeric_targets NAMESPACE rotlie:: FILE rotlieNumericTargets.cmake
        DESTINATION ${ROTLIE_INSTALL_CMAKEDIR})
if(ROTLIE_WITH_SYMBOLIC)
  install(EXPORT rotlie_symbolic_targets NAMESPACE rotlie:: FILE rotlieSymbolicTargets.cmake
          DESTINATION ${ROTLIE_INSTALL_CMAKEDIR})
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rotlieConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rotlieConfig.cmake INSTALL_DESTINATION ${ROTLIE_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rotlieConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rotlieConfig.cmake ${PROJECT_BINARY_DIR}/rotlieConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/rotlie_find_quadmath.cmake
        DESTINATION ${ROTLIE_INSTALL_CMAKEDIR})

# The package in the build tree (not installed): the same config file and version file, with targets
# that name the built libraries. Those keep their build-only link to rotlie::warnings (compile options
# for rotlie's own sources, never a consumer's: a static library's private link), exported from the
# build tree alone.
install(TARGETS rotlie_warnings EXPORT rotlie_build_tree_targets)  # an interface target: installs nothing
export(EXPORT rotlie_build_tree_targets NAMESPACE rotlie:: FILE ${PROJECT_BINARY_DIR}/rotlieBuildTreeTargets.cmake)
export(EXPORT rotlie_numeric_targets NAMESPACE rotlie:: FILE ${PROJECT_BINARY_DIR}/rotlieNumericTargets.cmake)
if(ROTLIE_WITH_SYMBOLIC)
  export(EXPORT rotlie_symbolic_targets NAMESPACE rotlie:: FILE ${PROJECT_BINARY_DIR}/rotlieSymbolicTargets.cmake)
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/rotlie_find_quadmath.cmake ${PROJECT_BINARY_DIR}/rotlie_find_quadmath.cmake COPYONLY)

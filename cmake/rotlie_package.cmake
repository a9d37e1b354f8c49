# The installed CMake package: find_package(rotlie) then rotlie::schemes, rotlie::models (component
# numeric, always) and rotlie::lie, bch, solver, runs, reports (component symbolic, when built).
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

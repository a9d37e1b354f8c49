# rotlie_add_library(NAME SOURCES … [DEPENDS …] [PRIVATE_DEPENDS …] EXPORT numeric|symbolic):
# the static library rotlie_NAME, alias rotlie::NAME (also its name in the installed package),
# public headers in NAME/include, C++20 required of every consumer, warnings for its own sources only.
function(rotlie_add_library name)
  cmake_parse_arguments(L "" "EXPORT" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  if(NOT L_EXPORT MATCHES "^(numeric|symbolic)$")
    message(FATAL_ERROR "rotlie_add_library(${name}): say which side of the package it belongs to: EXPORT numeric or EXPORT symbolic")
  endif()
  add_library(rotlie_${name} ${L_SOURCES})
  target_link_libraries(rotlie_${name} PUBLIC ${L_DEPENDS} PRIVATE ${L_PRIVATE_DEPENDS} $<BUILD_INTERFACE:rotlie::warnings>)
  rotlie_install_library(${name} ${L_EXPORT})
endfunction()

# rotlie_install_library(NAME numeric|symbolic): include paths for the build and install trees,
# cxx_std_20, the alias rotlie::NAME, and the install rules of the library and its headers into the
# export set of its side (the package's numeric or symbolic component).
function(rotlie_install_library name side)
  set(target rotlie_${name})
  add_library(rotlie::${name} ALIAS ${target})
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  else()
    set(scope PUBLIC)
  endif()
  target_include_directories(${target} ${scope} $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Consumers get C++20 from the targets. The libraries themselves compile as gnu++20: with
  # __STRICT_ANSI__ (-std=c++20) Boost 1.74's float128 functions do not compile.
  target_compile_features(${target} ${scope} cxx_std_20)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    set_target_properties(${target} PROPERTIES CXX_EXTENSIONS ON)
  endif()
  install(TARGETS ${target} EXPORT rotlie_${side}_targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
endfunction()

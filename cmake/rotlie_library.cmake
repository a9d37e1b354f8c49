# rotlie_add_library(NAME SOURCES … [DEPENDS …]): the library rotlie_NAME with alias rotlie::NAME,
# public headers in NAME/include, warnings applied.
function(rotlie_add_library name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(rotlie_${name} ${L_SOURCES})
  add_library(rotlie::${name} ALIAS rotlie_${name})
  target_include_directories(rotlie_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(rotlie_${name} PUBLIC ${L_DEPENDS} PRIVATE rotlie::warnings)
endfunction()

# GCC's libquadmath (behind Boost's float128) has no CMake package: check once that a program using
# it compiles and links. Used by the build and by the installed rotlieConfig.cmake.
include(CheckCXXSourceCompiles)
include(CMakePushCheckState)
cmake_push_check_state(RESET)
set(CMAKE_REQUIRED_LIBRARIES quadmath)
set(CMAKE_REQUIRED_QUIET ON)
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  # clang has __float128 but not GCC's <quadmath.h>: check with GCC's copy (fuzz/ gives the same to the build)
  execute_process(COMMAND gcc -print-file-name=include OUTPUT_VARIABLE rotlie_gcc_include OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(EXISTS "${rotlie_gcc_include}/quadmath.h")
    file(COPY "${rotlie_gcc_include}/quadmath.h" "${rotlie_gcc_include}/quadmath_weak.h"
         DESTINATION "${CMAKE_BINARY_DIR}/rotlie-quadmath-check")
    set(CMAKE_REQUIRED_INCLUDES "${CMAKE_BINARY_DIR}/rotlie-quadmath-check")
  endif()
endif()
check_cxx_source_compiles([[
#include <quadmath.h>
int main() { __float128 x = 2; return sqrtq(x) > 1 ? 0 : 1; }
]] ROTLIE_QUADMATH_LINKS)
cmake_pop_check_state()

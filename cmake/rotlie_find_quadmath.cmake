# GCC's libquadmath (behind Boost's float128) has no CMake package: check once that a program using
# it compiles and links. Used by the build and by the installed rotlieConfig.cmake.
include(CheckCXXSourceCompiles)
include(CMakePushCheckState)
cmake_push_check_state(RESET)
set(CMAKE_REQUIRED_LIBRARIES quadmath)
set(CMAKE_REQUIRED_QUIET ON)
check_cxx_source_compiles([[
#include <quadmath.h>
int main() { __float128 x = 2; return sqrtq(x) > 1 ? 0 : 1; }
]] ROTLIE_QUADMATH_LINKS)
cmake_pop_check_state()

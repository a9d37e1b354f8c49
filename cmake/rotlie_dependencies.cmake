# Third-party libraries, found through pkg-config (GiNaC, CLN) or their CMake packages.
# Installed on Debian 12 by scripts/install-deps.sh.
#
# Numeric side (schemes/, models/): Boost headers (Math, Multiprecision float128, Odeint), GCC's
# libquadmath and Highway. The symbolic side, reports and the CLI add GiNaC, CLN, Eigen, nlohmann_json and CLI11;
# a numeric-only build (ROTLIE_WITH_SYMBOLIC=OFF) never looks for them.
include(rotlie_find_quadmath)
if(NOT ROTLIE_QUADMATH_LINKS)
  message(FATAL_ERROR "libquadmath (GCC's __float128 library, used through Boost's float128) does not link")
endif()
# Highway (runtime dispatch to AVX2 or AVX-512): models_batch, the exact free flow of many bodies.
find_package(hwy 1.0 REQUIRED)
# Boost.Test for the tests.
if(ROTLIE_BUILD_TESTS)
  find_package(Boost 1.74 REQUIRED COMPONENTS unit_test_framework)
else()
  find_package(Boost 1.74 REQUIRED)
endif()

if(ROTLIE_WITH_SYMBOLIC)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(GINAC REQUIRED IMPORTED_TARGET ginac>=1.8)
  pkg_check_modules(CLN REQUIRED IMPORTED_TARGET cln>=1.3)
  pkg_check_modules(LZMA REQUIRED IMPORTED_TARGET liblzma)  # the shipped full-resolution maps (data/, .jsonl.xz)
  find_package(nlohmann_json 3.10 REQUIRED)
  find_package(Eigen3 3.4 REQUIRED NO_MODULE)
  find_package(CLI11 2.1 QUIET CONFIG)
  if(NOT CLI11_FOUND)
    find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
    add_library(CLI11::CLI11 INTERFACE IMPORTED)
    target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
  endif()
endif()

if(ROTLIE_BUILD_BENCH)
  find_package(benchmark QUIET)
  if(NOT benchmark_FOUND)
    message(STATUS "Google Benchmark not found: bench/ is skipped")
    set(ROTLIE_BUILD_BENCH OFF)
  endif()
endif()

# Warnings applied to every rotlie target (not to third-party headers).
add_library(rotlie_warnings INTERFACE)
target_compile_options(rotlie_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  # GCC 12 false positives inside libstdc++ (std::string and vector comparisons at -O2)
  -Wno-restrict -Wno-stringop-overread)
add_library(rotlie::warnings ALIAS rotlie_warnings)

# Warnings applied to every rotlie target (not to third-party headers).
add_library(rotlie_warnings INTERFACE)
target_compile_options(rotlie_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
add_library(rotlie::warnings ALIAS rotlie_warnings)

# Precompiled headers: most files of runs/, reports/, apps/ and python/ spend more time parsing
# the same headers (nlohmann/json, GiNaC, CLN, float128 and Boost.Math, the integrators' templates) than
# compiling their own code. Each such target parses its common headers once; a file then starts from
# the parsed state. The sanitize and fuzz presets build without them: a file that forgets an include
# still fails there.
option(ROTLIE_PRECOMPILED_HEADERS "Parse each target's common headers once (a fifth to a third less compile CPU in those folders)" ON)

# rotlie_precompile(TARGET HEADER…): angle-bracket headers, e.g. <nlohmann/json.hpp> or <rotlie/lie/rigid_body.hpp>.
function(rotlie_precompile target)
  if(ROTLIE_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
    # GCC 12 then reports its known false positive inside libstdc++'s string copies (char_traits.h,
    # std::string's operator+ inlined at -O3: GCC bug 105651), as -Wstringop-overflow or -Warray-bounds,
    # which it keeps quiet about without them
    target_compile_options(${target} PRIVATE "$<$<CXX_COMPILER_ID:GNU>:-Wno-stringop-overflow;-Wno-array-bounds>")
  endif()
endfunction()

# Precompiled headers: most files of runs/, reports/, apps/ and python/ spend more time parsing
# the same headers (nlohmann/json, GiNaC, CLN, float128 and Boost.Math, the integrators' templates) than
# compiling their own code. Each such target parses its common headers once; a file then starts from
# the parsed state. The sanitize preset builds without them, so that a file that forgets an include
# still fails somewhere.
option(ROTLIE_PRECOMPILED_HEADERS "Parse each target's common headers once (about a third less build CPU)" ON)

# rotlie_precompile(TARGET HEADER…): angle-bracket headers, e.g. <nlohmann/json.hpp> or <rotlie/lie/rigid_body.hpp>.
function(rotlie_precompile target)
  if(ROTLIE_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

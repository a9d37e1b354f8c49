# Unity sources for the targets whose files share heavy headers and templates (nlohmann/json, GiNaC
# and CLN, pybind11, the integrators): a batch of files compiles as one translation unit, so the inline
# functions those headers instantiate are compiled and optimised once per batch instead of once per
# file, and a precompiled header is loaded once per batch. Each file keeps its names inside its own
# namespaces (a file-scope helper must not meet another file's in the same batch).
option(ROTLIE_UNITY_BUILD "Compile the libraries' and programs' files in unity batches (about a third less build CPU)" ON)

# rotlie_unity(TARGET BATCH_SIZE)
function(rotlie_unity target batch)
  if(ROTLIE_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
  endif()
endfunction()

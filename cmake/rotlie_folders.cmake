# The project's folders in dependency order, one list for the libraries (top level) and their tests
# (tests/): the symbolic side and what stands on it only when ROTLIE_WITH_SYMBOLIC is on.
set(ROTLIE_FOLDERS_BELOW lie bch solver)        # the symbolic side (GiNaC, CLN)
set(ROTLIE_FOLDERS_NUMERIC schemes models)
set(ROTLIE_FOLDERS_ABOVE runs reports apps python)  # on both sides: the library floor and its front ends (python: the module)

# add_subdirectory for every folder of this build, in order.
# rotlie_add_folders([ONLY folder…]): with ONLY and a non-empty list, just those of them.
function(rotlie_add_folders)
  cmake_parse_arguments(F "" "" "ONLY" ${ARGN})
  set(folders ${ROTLIE_FOLDERS_NUMERIC})
  if(ROTLIE_WITH_SYMBOLIC)
    set(folders ${ROTLIE_FOLDERS_BELOW} ${ROTLIE_FOLDERS_NUMERIC} ${ROTLIE_FOLDERS_ABOVE})
  endif()
  foreach(folder IN LISTS folders)
    if(F_ONLY AND NOT folder IN_LIST F_ONLY)
      continue()
    endif()
    add_subdirectory(${folder})
  endforeach()
endfunction()

# The dependency rule of the layers, checked when the build is configured:
# a target named here must not link, directly or through any library it
# links, one of the forbidden libraries. A violation stops the configure
# with the chain that brought the library in, so that an include added for
# convenience cannot quietly pull a window into a headless tool.
#
#   hemiroll_forbid_links(TARGET hemiroll_research FORBIDDEN PkgConfig::SDL2 ...)

# Everything `item` links, as "a -> b -> c" chains, into `out_chains`.
function(_hemiroll_link_closure item chain out_chains)
  set(result "${${out_chains}}")
  if(NOT TARGET "${item}")
    set(${out_chains} "${result}" PARENT_SCOPE)
    return()
  endif()
  get_target_property(type "${item}" TYPE)
  set(links "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(direct "${item}" LINK_LIBRARIES)
    if(direct)
      list(APPEND links ${direct})
    endif()
  endif()
  get_target_property(usage "${item}" INTERFACE_LINK_LIBRARIES)
  if(usage)
    list(APPEND links ${usage})
  endif()
  foreach(link IN LISTS links)
    # A static library's private links reach its users as $<LINK_ONLY:x>.
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
    if(link MATCHES "^\\$<" OR link STREQUAL "")
      continue()
    endif()
    set(next "${chain} -> ${link}")
    if(NOT "${next}" IN_LIST result AND NOT chain MATCHES " -> ${link}( |$)")
      list(APPEND result "${next}")
      _hemiroll_link_closure("${link}" "${next}" result)
    endif()
  endforeach()
  set(${out_chains} "${result}" PARENT_SCOPE)
endfunction()

function(hemiroll_forbid_links)
  cmake_parse_arguments(ARG "" "TARGET" "FORBIDDEN" ${ARGN})
  set(chains "")
  _hemiroll_link_closure("${ARG_TARGET}" "${ARG_TARGET}" chains)
  foreach(chain IN LISTS chains)
    foreach(forbidden IN LISTS ARG_FORBIDDEN)
      if(chain MATCHES " -> ${forbidden}$")
        message(FATAL_ERROR "layer rule broken: ${ARG_TARGET} must not link ${forbidden}, but ${chain} "
                            "(docs/ARCHITECTURE.md, Layers)")
      endif()
    endforeach()
  endforeach()
endfunction()

# The order in which the OpenImageIO module's libraries are searched for symbols.
#
# Loading libdrt_oiio.so costs a render most of its fixed CPU time, and most of
# that is the dynamic loader resolving about 170,000 symbol references of the
# ~260 libraries Debian's OpenImageIO needs (they are linked with immediate
# binding). The loader looks each symbol up library by library, in the order of
# the module's search list: the executable's libraries, then the module's own
# dependencies breadth first. In OpenImageIO's own order the libraries that
# define most of the symbols (OpenVDB, Xerces, GDAL, GEOS: C++ libraries whose
# references to their own symbols are resolved through that list too) come a
# hundred or more libraries down, so a lookup walked 115 libraries on average.
#
# drt_oiio_load_order(TARGET LIBRARY) makes TARGET name every library of
# LIBRARY's dependency closure that defines at least 100 dynamic symbols as a
# direct dependency, those with the most symbols first: the search list then
# starts with them (about 52 libraries a lookup), and the module loads in about
# two thirds of the CPU time (docs/performance.md, "The fixed cost of a render").
# Nothing else changes: the same libraries are loaded, and symbols defined once
# are found where they were; a symbol defined in several libraries (C++ inline
# functions and type information, identical by the one-definition rule) may be
# taken from another of its copies.
#
# The list is computed at configure time (nm of each library, a few seconds) and
# cached per library path; without nm, or for a library that is not a shared
# object, TARGET links as before.

if(CMAKE_SCRIPT_MODE_FILE)
  # cmake -DLIBRARY=... -DNM=... -DOUTPUT=... -P OiioLoadOrder.cmake
  file(GET_RUNTIME_DEPENDENCIES LIBRARIES "${LIBRARY}" RESOLVED_DEPENDENCIES_VAR deps
       UNRESOLVED_DEPENDENCIES_VAR unresolved)
  set(keyed "")
  foreach(dep IN LISTS deps)
    get_filename_component(name "${dep}" NAME)
    # The C and C++ runtimes are searched early already (the executable needs them).
    if(name MATCHES "^(libc|libm|libstdc\\+\\+|libgcc_s|ld-linux.*)\\.so")
      continue()
    endif()
    execute_process(COMMAND "${NM}" -D --defined-only "${dep}" OUTPUT_VARIABLE symbols
                    RESULT_VARIABLE failed ERROR_QUIET)
    if(failed)
      continue()
    endif()
    string(REGEX MATCHALL "\n" lines "${symbols}")
    list(LENGTH lines count)
    if(count LESS 100)
      continue()
    endif()
    # Sortable key: the count's complement, zero-padded, then the path.
    math(EXPR key "99999999 - ${count}")
    string(LENGTH "${key}" digits)
    while(digits LESS 8)
      string(PREPEND key "0")
      math(EXPR digits "${digits} + 1")
    endwhile()
    list(APPEND keyed "${key}|${dep}")
  endforeach()
  list(SORT keyed)
  set(ordered "")
  foreach(entry IN LISTS keyed)
    string(REGEX REPLACE "^[0-9]+\\|" "" path "${entry}")
    list(APPEND ordered "${path}")
  endforeach()
  file(WRITE "${OUTPUT}" "${ordered}")
  return()
endif()

set(DRT_OIIO_LOAD_ORDER_SCRIPT "${CMAKE_CURRENT_LIST_FILE}")

function(drt_oiio_load_order target imported)
  if(NOT CMAKE_SYSTEM_NAME STREQUAL "Linux" OR NOT CMAKE_NM)
    return()
  endif()
  get_target_property(location ${imported} IMPORTED_LOCATION)
  if(NOT location)
    get_target_property(configs ${imported} IMPORTED_CONFIGURATIONS)
    foreach(config IN LISTS configs)
      get_target_property(location ${imported} IMPORTED_LOCATION_${config})
      if(location)
        break()
      endif()
    endforeach()
  endif()
  if(NOT location OR NOT location MATCHES "\\.so(\\.|$)")
    return()
  endif()
  if(NOT DRT_OIIO_LOAD_ORDER_FOR STREQUAL location)
    set(output "${CMAKE_BINARY_DIR}/oiio_load_order.txt")
    execute_process(COMMAND "${CMAKE_COMMAND}" -DLIBRARY=${location} -DNM=${CMAKE_NM} -DOUTPUT=${output}
                            -P "${DRT_OIIO_LOAD_ORDER_SCRIPT}"
                    RESULT_VARIABLE failed OUTPUT_QUIET ERROR_QUIET)
    set(order "")
    if(NOT failed AND EXISTS "${output}")
      file(READ "${output}" order)
    endif()
    set(DRT_OIIO_LOAD_ORDER "${order}" CACHE INTERNAL "libraries the OpenImageIO module searches first")
    set(DRT_OIIO_LOAD_ORDER_FOR "${location}" CACHE INTERNAL "the library DRT_OIIO_LOAD_ORDER is for")
  endif()
  if(DRT_OIIO_LOAD_ORDER)
    list(LENGTH DRT_OIIO_LOAD_ORDER count)
    message(STATUS "OpenImageIO module: ${count} libraries searched first, most symbols first")
    target_link_libraries(${target} PRIVATE "-Wl,--push-state,--no-as-needed" ${DRT_OIIO_LOAD_ORDER}
                          "-Wl,--pop-state")
  endif()
endfunction()

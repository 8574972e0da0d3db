# Finds the SuiteSparse pieces we use (CHOLMOD, UMFPACK and their dependencies) and defines
# SuiteSparse::CHOLMOD and SuiteSparse::UMFPACK. Debian ships no CMake config for SuiteSparse 5.
find_path(SuiteSparse_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
foreach(lib cholmod umfpack amd colamd camd ccolamd suitesparseconfig)
  string(TOUPPER ${lib} LIB)
  find_library(SuiteSparse_${LIB}_LIBRARY ${lib})
  list(APPEND _ss_vars SuiteSparse_${LIB}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR ${_ss_vars})
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::config INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::config PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_SUITESPARSECONFIG_LIBRARY}")
  add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES INTERFACE_LINK_LIBRARIES
    "${SuiteSparse_CHOLMOD_LIBRARY};${SuiteSparse_AMD_LIBRARY};${SuiteSparse_COLAMD_LIBRARY};${SuiteSparse_CAMD_LIBRARY};${SuiteSparse_CCOLAMD_LIBRARY};SuiteSparse::config")
  add_library(SuiteSparse::UMFPACK INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES INTERFACE_LINK_LIBRARIES
    "${SuiteSparse_UMFPACK_LIBRARY};SuiteSparse::CHOLMOD")
endif()
mark_as_advanced(SuiteSparse_INCLUDE_DIR ${_ss_vars})

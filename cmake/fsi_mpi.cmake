# The optional MPI decomposition (parallel/, issue 47): MPI (C++ bindings not needed, the C API
# through MPI::MPI_CXX) and Zoltan. Debian's libtrilinos-zoltan-dev puts zoltan.h in
# /usr/include/trilinos and ships a ZoltanConfig.cmake whose target names the Scotch
# development libraries (not installed with it), so the header and library are found directly.
# FSI_MPI=AUTO: built if both are found, else one status line; ON: an error if missing; OFF: off.
set(FSI_HAVE_MPI OFF)
if(NOT FSI_MPI STREQUAL "OFF")
  find_package(MPI COMPONENTS CXX QUIET)
  find_path(FSI_ZOLTAN_INCLUDE_DIR zoltan.h PATH_SUFFIXES trilinos)
  find_library(FSI_ZOLTAN_LIBRARY NAMES trilinos_zoltan zoltan)
  if(MPI_CXX_FOUND AND FSI_ZOLTAN_INCLUDE_DIR AND FSI_ZOLTAN_LIBRARY)
    set(FSI_HAVE_MPI ON)
    message(STATUS "FSI_MPI: MPI ${MPI_CXX_VERSION} and Zoltan (${FSI_ZOLTAN_LIBRARY}): "
                   "building parallel/ and its mpi tests")
  elseif(FSI_MPI STREQUAL "ON")
    message(FATAL_ERROR "FSI_MPI=ON needs MPI and Zoltan (scripts/setup installs "
                        "libopenmpi-dev openmpi-bin libtrilinos-zoltan-dev)")
  endif()
endif()
if(NOT FSI_HAVE_MPI)
  message(STATUS "FSI_MPI: off (FSI_MPI=${FSI_MPI}; MPI or Zoltan not found or not asked): "
                 "serial build, no parallel/")
endif()

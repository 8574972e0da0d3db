# The HDF5 library every target that reads or writes HDF5 links (fsi_hdf5): Debian's parallel
# HDF5 (libhdf5-openmpi-dev, built with H5_HAVE_PARALLEL) when the MPI decomposition is built and
# it is installed, so fields.h5 is written collectively under mpirun (issue 47); otherwise the
# serial one find_package(HDF5) found, as before. One library for the whole program: the two
# variants export the same symbols. The parallel one runs serial files (sec2 driver) unchanged.
# FSI_PARALLEL_HDF5=OFF keeps the serial one (rank 0 writes the frames gathered to it).
option(FSI_PARALLEL_HDF5 "With MPI: link Debian's parallel HDF5 when installed" ON)
add_library(fsi_hdf5 INTERFACE)
set(FSI_HAVE_PARALLEL_HDF5 OFF)
if(FSI_HAVE_MPI AND FSI_PARALLEL_HDF5)
  find_path(FSI_HDF5_MPI_INCLUDE_DIR H5pubconf.h PATHS /usr/include/hdf5/openmpi NO_DEFAULT_PATH)
  find_library(FSI_HDF5_MPI_LIBRARY hdf5 PATHS /usr/lib/x86_64-linux-gnu/hdf5/openmpi
               NO_DEFAULT_PATH)
  if(FSI_HDF5_MPI_INCLUDE_DIR AND FSI_HDF5_MPI_LIBRARY)
    file(STRINGS ${FSI_HDF5_MPI_INCLUDE_DIR}/H5pubconf.h _fsi_h5_parallel
         REGEX "^#define H5_HAVE_PARALLEL 1")
    if(_fsi_h5_parallel)
      set(FSI_HAVE_PARALLEL_HDF5 ON)
    endif()
  endif()
endif()
if(FSI_HAVE_PARALLEL_HDF5)
  message(STATUS "HDF5: parallel (${FSI_HDF5_MPI_LIBRARY}): fields.h5 written collectively "
                 "under mpirun")
  target_include_directories(fsi_hdf5 SYSTEM INTERFACE ${FSI_HDF5_MPI_INCLUDE_DIR})
  target_link_libraries(fsi_hdf5 INTERFACE ${FSI_HDF5_MPI_LIBRARY} MPI::MPI_CXX)
else()
  message(STATUS "HDF5: serial (under mpirun rank 0 writes fields.h5; "
                 "MPI and libhdf5-openmpi-dev give the collective write)")
  target_link_libraries(fsi_hdf5 INTERFACE hdf5::hdf5)
endif()

# The installable CMake package: `cmake --install build --prefix P` puts the libraries, their
# public headers and the fsi command under P with P/lib/cmake/fsi/fsiConfig.cmake, so another
# project does `find_package(fsi)` and links fsi::core, fsi::coupling, fsi::structure_fem, ...
# Included at the end of the root CMakeLists.txt: the targets exist, their properties are
# adjusted here (read at generate time) without touching the libraries' own files.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Target -> exported name fsi::<name>. fsi_app's plug-in headers (apps/solvers) go to
# include/fsi_solvers, every <lib>/include to include/.
set(FSI_PACKAGE_TARGETS
    fsi_core:core particles:particles materials:materials geometry_erp:geometry_erp
    structure_fem:structure_fem solid_tlsph:solid_tlsph coupling:coupling fluid_emps:fluid_emps
    fluid_sph:fluid_sph fsi_app:app)

set(_fsi_installed)
foreach(pair ${FSI_PACKAGE_TARGETS})
  string(REPLACE ":" ";" pair "${pair}")
  list(GET pair 0 target)
  list(GET pair 1 name)
  list(APPEND _fsi_installed ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  get_target_property(type ${target} TYPE)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    # The Python module (python/) links these static libraries into a shared object.
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  endif()
  # Include directories: the source folders in the build tree, include/ under the prefix.
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  set(wrapped)
  foreach(dir ${dirs})
    get_filename_component(base ${dir} NAME)
    if(base STREQUAL "include")
      set(dest ${CMAKE_INSTALL_INCLUDEDIR})
    else()
      set(dest ${CMAKE_INSTALL_INCLUDEDIR}/fsi_${base})
    endif()
    list(APPEND wrapped "$<BUILD_INTERFACE:${dir}>" "$<INSTALL_INTERFACE:${dest}>")
    install(DIRECTORY ${dir}/ DESTINATION ${dest} FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
  endforeach()
  list(REMOVE_DUPLICATES wrapped)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${wrapped}")
  # The project's warning (and sanitizer) flags stay in this build: a user's code is not
  # compiled with -Werror by linking fsi::core.
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(links)
    list(TRANSFORM links REPLACE "^fsi_flags$" "$<BUILD_INTERFACE:fsi_flags>")
    list(TRANSFORM links REPLACE "^\\$<LINK_ONLY:fsi_flags>$" "$<LINK_ONLY:$<BUILD_INTERFACE:fsi_flags>>")
    set_target_properties(${target} PROPERTIES INTERFACE_LINK_LIBRARIES "${links}")
  endif()
endforeach()
set_target_properties(fsi PROPERTIES EXPORT_NAME fsi)
set_target_properties(fsi_hdf5 PROPERTIES EXPORT_NAME hdf5) # fsi::hdf5, the one fsi::app links

install(TARGETS ${_fsi_installed} fsi fsi_hdf5 EXPORT fsiTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(FSI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fsi)
install(EXPORT fsiTargets NAMESPACE fsi:: DESTINATION ${FSI_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/fsiConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/fsiConfig.cmake INSTALL_DESTINATION ${FSI_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/fsiConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/fsiConfig.cmake ${PROJECT_BINARY_DIR}/fsiConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindSuiteSparse.cmake
        DESTINATION ${FSI_CMAKE_DIR})


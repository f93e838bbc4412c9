# `cmake --install BUILD [--prefix P]` (docs/install.md): the shockfield command, the library
# libshockfield.a with its public headers, a CMake package (find_package(shockfield), target
# shockfield::shockfield), a pkg-config file, the Python packages (the module when built, the
# plot helpers always). The installed command finds the Python packages relative to itself
# (BIN/../SHOCKFIELD_PYTHON_INSTALL_DIR, app/python_helpers.cpp), never through the source tree.
include(CMakePackageConfigHelpers)
set(SHOCKFIELD_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shockfield)

set_property(SOURCE ${CMAKE_SOURCE_DIR}/src/shockfield/app/python_helpers.cpp APPEND PROPERTY
  COMPILE_DEFINITIONS SHOCKFIELD_BIN_TO_PYTHON="../${SHOCKFIELD_PYTHON_INSTALL_DIR}")

# Programs using the headers need C++20 too (the build sets it with CMAKE_CXX_STANDARD).
target_compile_features(shockfield_lib PUBLIC cxx_std_20)

install(TARGETS shockfield RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS shockfield_lib EXPORT shockfieldTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/src/shockfield DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp" PATTERN "app" EXCLUDE)
install(EXPORT shockfieldTargets NAMESPACE shockfield:: DESTINATION ${SHOCKFIELD_CMAKE_INSTALL_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/shockfieldConfig.cmake.in
  ${CMAKE_BINARY_DIR}/shockfieldConfig.cmake INSTALL_DESTINATION ${SHOCKFIELD_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/shockfieldConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/shockfieldConfig.cmake ${CMAKE_BINARY_DIR}/shockfieldConfigVersion.cmake
  DESTINATION ${SHOCKFIELD_CMAKE_INSTALL_DIR})

# pkg-config: the include and link flags of the library and of the libraries it uses.
string(REPLACE ";" " -I" shockfield_pc_hdf5_cflags "-I${HDF5_INCLUDE_DIRS}")
string(REPLACE ";" " " shockfield_pc_hdf5_libs "${HDF5_C_LIBRARIES}")
# Built with SHOCKFIELD_MPI: the MPI libraries too (Open MPI's ompi-cxx.pc is not always there).
if(SHOCKFIELD_MPI)
  string(REPLACE ";" " " shockfield_pc_mpi_libs "${MPI_CXX_LIBRARIES}")
  string(APPEND shockfield_pc_hdf5_libs " ${shockfield_pc_mpi_libs}")
endif()
# The prefix is found from the .pc file's own place, so the tree can be moved after installing.
file(RELATIVE_PATH shockfield_pc_to_prefix /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(${CMAKE_SOURCE_DIR}/cmake/shockfield.pc.in ${CMAKE_BINARY_DIR}/shockfield.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/shockfield.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(DIRECTORY ${CMAKE_SOURCE_DIR}/python/shockfield_plot ${CMAKE_SOURCE_DIR}/python/shockfield
  DESTINATION ${SHOCKFIELD_PYTHON_INSTALL_DIR} PATTERN "__pycache__" EXCLUDE)
if(SHOCKFIELD_PYTHON_MODULE)
  install(TARGETS shockfield_python LIBRARY DESTINATION ${SHOCKFIELD_PYTHON_INSTALL_DIR}/shockfield)
endif()

# The Python side (docs/python.md): the `shockfield` package (python/shockfield, pure Python plus
# the pybind11 module shockfield._core built from the same library) and the plot helpers
# (python/shockfield_plot). Both are assembled in BUILD/python (PYTHONPATH for the tests)
# and installed to SHOCKFIELD_PYTHON_INSTALL_DIR under the prefix.
#
# Which Python: Debian's /usr/bin/python3 when it exists (it sees Debian's numpy), else python3
# on PATH; set SHOCKFIELD_PYTHON_EXECUTABLE to choose another. Without pybind11 (Debian
# pybind11-dev) or the interpreter's headers the module is skipped, and the C++ build goes on.
if(EXISTS /usr/bin/python3)
  set(shockfield_default_python /usr/bin/python3)
else()
  find_program(shockfield_default_python python3)
endif()
set(SHOCKFIELD_PYTHON_EXECUTABLE "${shockfield_default_python}" CACHE FILEPATH
  "Python interpreter the shockfield module is built for")
option(SHOCKFIELD_BUILD_PYTHON "Build the Python module (needs pybind11)" ON)

set(Python_EXECUTABLE "${SHOCKFIELD_PYTHON_EXECUTABLE}")
find_package(Python 3.8 QUIET COMPONENTS Interpreter Development.Module)
# Under lib/, not the multiarch CMAKE_INSTALL_LIBDIR (lib/x86_64-linux-gnu for /usr), where no
# interpreter looks; python/shockfield/case.py finds PREFIX/bin from there.
if(Python_Interpreter_FOUND)
  set(shockfield_python_dir "lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages")
  # Debian's interpreters look in dist-packages under /usr/local and /usr.
  if(Python_EXECUTABLE MATCHES "^/usr/bin/")
    string(REPLACE "site-packages" "dist-packages" shockfield_python_dir "${shockfield_python_dir}")
  endif()
else()
  set(shockfield_python_dir "lib/python3/site-packages")
endif()
set(SHOCKFIELD_PYTHON_INSTALL_DIR "${shockfield_python_dir}" CACHE STRING
  "Where the Python packages go, relative to the install prefix")

set(SHOCKFIELD_PYTHON_BUILD_DIR ${CMAKE_BINARY_DIR}/python)
file(GLOB_RECURSE shockfield_python_files CONFIGURE_DEPENDS RELATIVE ${CMAKE_SOURCE_DIR}/python
  ${CMAKE_SOURCE_DIR}/python/shockfield/*.py ${CMAKE_SOURCE_DIR}/python/shockfield/*.pyi
  ${CMAKE_SOURCE_DIR}/python/shockfield/py.typed ${CMAKE_SOURCE_DIR}/python/shockfield_plot/*.py)
foreach(file ${shockfield_python_files})
  configure_file(${CMAKE_SOURCE_DIR}/python/${file} ${SHOCKFIELD_PYTHON_BUILD_DIR}/${file} COPYONLY)
endforeach()

set(SHOCKFIELD_PYTHON_MODULE OFF)
if(SHOCKFIELD_BUILD_PYTHON)
  if(NOT Python_Development.Module_FOUND)
    message(STATUS "shockfield: Python module skipped: no Python headers for ${SHOCKFIELD_PYTHON_EXECUTABLE} (Debian: python3-dev)")
  else()
    find_package(pybind11 2.6 CONFIG QUIET)
    if(NOT pybind11_FOUND)
      message(STATUS "shockfield: Python module skipped: pybind11 not found (Debian: apt install pybind11-dev python3-pybind11)")
    else()
      set(SHOCKFIELD_PYTHON_MODULE ON)
    endif()
  endif()
endif()

if(SHOCKFIELD_PYTHON_MODULE)
  message(STATUS "shockfield: Python module for ${Python_EXECUTABLE} (${Python_VERSION}), pybind11 ${pybind11_VERSION}")
  # A shared module needs position-independent code, so the library is built with -fPIC when
  # the module is (Debian's g++ builds PIE executables by default, --enable-default-pie, so the
  # library's code is position-independent either way; bench/RESULTS.md measured -fPIC against
  # it). -fno-semantic-interposition keeps the calls between the library's own functions direct
  # and inlinable as under -fPIE. The module links the library: one build of every source.
  set_target_properties(shockfield_lib PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_compile_options(shockfield_lib PRIVATE -fno-semantic-interposition)
  file(GLOB shockfield_binding_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/python/src/*.cpp)
  # NO_EXTRAS: no LTO (the library is built without it, and its serial link is slow on CI).
  pybind11_add_module(shockfield_python MODULE NO_EXTRAS ${shockfield_binding_sources})
  target_link_libraries(shockfield_python PRIVATE shockfield_lib)
  # Hidden symbols: the module exports only its init function, not the library it contains.
  target_link_options(shockfield_python PRIVATE -Wl,--exclude-libs,ALL)
  set_target_properties(shockfield_python PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    OUTPUT_NAME _core
    LIBRARY_OUTPUT_DIRECTORY ${SHOCKFIELD_PYTHON_BUILD_DIR}/shockfield)
  set_property(SOURCE ${CMAKE_SOURCE_DIR}/src/shockfield/app/version_text.cpp APPEND PROPERTY COMPILE_DEFINITIONS
    "SHOCKFIELD_PYTHON_MODULE_FOR=\"Python ${Python_VERSION} at ${Python_EXECUTABLE}, pybind11 ${pybind11_VERSION}\"")
endif()

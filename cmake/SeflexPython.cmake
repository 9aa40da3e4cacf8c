# Whether the Python module (python/) is built: SEFLEX_PYTHON=ON, or AUTO (default) when Python 3 with
# its headers (python3-dev) and pybind11 (pybind11-dev) are found; sets SEFLEX_PYTHON_BUILT and
# SEFLEX_PYTHON_EXECUTABLE. The module links the static libraries into a shared object, so
# python/CMakeLists.txt compiles those it links position-independent (-fPIC, with
# -fno-semantic-interposition so that calls inside a library are inlined as in the -fPIE build).
# The interpreter is Debian's /usr/bin/python3 when it exists (the one python3-numpy and the other
# packages of scripts/install-deps.sh belong to), whatever python3 comes first on PATH; choose
# another with -DPython3_EXECUTABLE=/path/to/python3.
set(SEFLEX_PYTHON AUTO CACHE STRING "Build the Python module: AUTO (when Python 3 and pybind11 are found), ON or OFF")
set_property(CACHE SEFLEX_PYTHON PROPERTY STRINGS AUTO ON OFF)
if(SEFLEX_PYTHON STREQUAL "OFF" OR (SEFLEX_PYTHON STREQUAL "AUTO" AND SEFLEX_SANITIZE))
  # AUTO leaves the module out of sanitizer builds (build-fuzz): an ASan module needs the runtime
  # preloaded into python3, and those builds run only the input and cards tests.
  set(SEFLEX_PYTHON_BUILT OFF)
  return()
endif()

if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the seflex module is built for")
endif()
if(SEFLEX_PYTHON STREQUAL "ON")
  find_package(Python3 COMPONENTS Interpreter Development.Module REQUIRED)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 CONFIG REQUIRED)
else()
  find_package(Python3 COMPONENTS Interpreter Development.Module)
  if(Python3_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(NOT Python3_FOUND OR NOT pybind11_FOUND)
    message(STATUS "seflex Python module: not built (needs python3-dev and pybind11-dev: scripts/install-deps.sh)")
    set(SEFLEX_PYTHON_BUILT OFF)
  endif()
endif()
if(NOT DEFINED SEFLEX_PYTHON_BUILT)
  set(SEFLEX_PYTHON_BUILT ON)
  message(STATUS "seflex Python module: for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
  set(SEFLEX_PYTHON_EXECUTABLE ${Python3_EXECUTABLE})
endif()

# Finds what the Python module needs and defines SEGMAT_BUILD_PYTHON (on when pybind11 is found).
# The module is built for one interpreter: /usr/bin/python3 when it exists (Debian's numpy,
# pytest and Open3D belong to it), else the first python3 found; -DPython3_EXECUTABLE=... chooses.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Interpreter the Python module is built for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
if(Python3_FOUND)
  # pybind11 then builds for the Python3 found above (its FindPython mode).
  find_package(pybind11 CONFIG QUIET)
endif()
if(Python3_FOUND AND pybind11_FOUND)
  set(SEGMAT_PYTHON_DEFAULT ON)
else()
  set(SEGMAT_PYTHON_DEFAULT OFF)
endif()
option(SEGMAT_BUILD_PYTHON "Build the Python module segmat (pybind11)" ${SEGMAT_PYTHON_DEFAULT})
if(SEGMAT_BUILD_PYTHON AND NOT (Python3_FOUND AND pybind11_FOUND))
  message(FATAL_ERROR "SEGMAT_BUILD_PYTHON needs python3-dev and pybind11-dev")
endif()

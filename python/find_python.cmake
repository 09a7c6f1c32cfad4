# Finds the Python interpreter the module is built for, with NumPy and pybind11; sets
# IMPLICITFIT_PYTHON_FOUND (and IMPLICITFIT_PYTHON_MISSING, what is missing, when not found).
#
# The interpreter: -DPython_EXECUTABLE=... when given; otherwise the first of /usr/bin/python3
# (Debian's interpreter, the one python3-numpy and python3-pybind11 install into) and the
# `python3` first on PATH (often a pyenv or virtualenv one) that can `import numpy`. Trying
# /usr/bin/python3 first matters: FindPython alone would take the first python3 on PATH, and a
# pyenv interpreter without NumPy would turn the module off.
set(IMPLICITFIT_PYTHON_FOUND OFF)
set(IMPLICITFIT_PYTHON_MISSING "")
if(NOT Python_EXECUTABLE)
  find_program(_implicitfit_path_python3 NAMES python3 NO_CACHE)
  foreach(_candidate /usr/bin/python3 ${_implicitfit_path_python3})
    if(EXISTS "${_candidate}")
      execute_process(COMMAND "${_candidate}" -c "import numpy"
                      RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
      if(_rc EQUAL 0)
        set(Python_EXECUTABLE "${_candidate}" CACHE FILEPATH
            "Python interpreter the implicitfit module is built for (must have NumPy)")
        break()
      endif()
    endif()
  endforeach()
endif()
if(NOT Python_EXECUTABLE)
  set(IMPLICITFIT_PYTHON_MISSING "a Python 3 interpreter with NumPy (Debian: python3-numpy)")
  return()
endif()
find_package(Python 3.7 QUIET COMPONENTS Interpreter Development.Module NumPy)
if(NOT Python_Interpreter_FOUND OR NOT Python_NumPy_FOUND)
  set(IMPLICITFIT_PYTHON_MISSING "NumPy for ${Python_EXECUTABLE} (Debian: python3-numpy)")
  return()
endif()
if(NOT Python_Development.Module_FOUND)
  set(IMPLICITFIT_PYTHON_MISSING "the Python headers for ${Python_EXECUTABLE} (Debian: python3-dev)")
  return()
endif()
# pybind11's CMake package: Debian's pybind11-dev (/usr/lib/cmake/pybind11), or the one of a
# pip-installed pybind11 of that interpreter.
execute_process(COMMAND "${Python_EXECUTABLE}" -c "import pybind11; print(pybind11.get_cmake_dir())"
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _pybind11_hint
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
find_package(pybind11 2.6 CONFIG QUIET HINTS ${_pybind11_hint})
if(NOT pybind11_FOUND)
  set(IMPLICITFIT_PYTHON_MISSING "pybind11 (Debian: pybind11-dev)")
  return()
endif()
set(IMPLICITFIT_PYTHON_FOUND ON)

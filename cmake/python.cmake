# Decides whether the Python module (python/) is built: MODALTYRE_PYTHON is ON when pybind11,
# the Python headers and NumPy are found (Debian: pybind11-dev python3-dev python3-numpy), and
# the build is not instrumented. Sanitizer and fuzz builds leave it out: an ASan-instrumented
# extension cannot be loaded into the uninstrumented python3.
set(MODALTYRE_PYTHON OFF)
if(NOT MODALTYRE_BUILD_PYTHON)
  message(STATUS "Python module: not built (MODALTYRE_BUILD_PYTHON=OFF)")
  return()
endif()
if(MODALTYRE_SANITIZE OR MODALTYRE_FUZZ)
  message(STATUS "Python module: not built in a sanitizer or fuzz build (an instrumented "
                 "extension cannot be loaded into the uninstrumented python3)")
  return()
endif()
# The first python3 on the PATH may be a separate interpreter without Debian's NumPy (pyenv):
# unless Python3_EXECUTABLE is given, take the first of the PATH's and Debian's that has NumPy,
# so that the module is built for, and tested with, an interpreter that can use it.
if(NOT Python3_EXECUTABLE)
  find_program(_modaltyre_path_python3 NAMES python3 NO_CACHE)
  foreach(candidate IN ITEMS ${_modaltyre_path_python3} /usr/bin/python3)
    execute_process(COMMAND ${candidate} -c "import numpy" RESULT_VARIABLE rc OUTPUT_QUIET
                    ERROR_QUIET)
    if(rc EQUAL 0)
      set(Python3_EXECUTABLE ${candidate} CACHE FILEPATH "python3 the module is built for")
      break()
    endif()
  endforeach()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(NOT Python3_FOUND OR NOT pybind11_FOUND)
  message(WARNING "Python module: not built: needs pybind11, the Python headers and NumPy "
                  "(Debian: pybind11-dev python3-dev python3-numpy; scripts/install-deps.sh)")
  return()
endif()
# Where `cmake --install` puts the package, relative to the install prefix. Debian's python3
# (default scheme posix_local) searches PREFIX/lib/python3.X/dist-packages for the prefixes
# /usr/local and /usr, but not lib/python3/dist-packages under /usr/local (that one is Debian's
# own packages' folder under /usr): take the version's folder, so that the default prefix
# /usr/local needs no PYTHONPATH. Elsewhere: the interpreter's site directory relative to its
# prefix.
execute_process(
  COMMAND ${Python3_EXECUTABLE} -c
          "import os, sys, sysconfig\n\
if getattr(sysconfig, 'get_default_scheme', str)() == 'posix_local':\n\
    site = sysconfig.get_paths('posix_local', vars={'base': '/usr', 'platbase': '/usr'})['platlib']\n\
    print(os.path.relpath(site, '/usr/local'))\n\
else:\n\
    print(os.path.relpath(sysconfig.get_paths()['platlib'], sys.prefix))"
  OUTPUT_VARIABLE _modaltyre_site OUTPUT_STRIP_TRAILING_WHITESPACE)
set(MODALTYRE_PYTHON_INSTALL_DIR ${_modaltyre_site} CACHE STRING
    "Python package directory under the install prefix")
set(MODALTYRE_PYTHON ON)
message(STATUS "Python module: built for ${Python3_EXECUTABLE} (${Python3_VERSION}); "
               "installed into PREFIX/${MODALTYRE_PYTHON_INSTALL_DIR}")

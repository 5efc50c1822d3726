# Finds what the Python module (python/) needs: a Python 3 interpreter with its headers, and
# pybind11 (Debian's pybind11-dev). Sets ENVCRUST_PYTHON_FOUND; finds nothing loudly.
#
# Debian's python3-numpy and python3-pytest install for /usr/bin/python3, so that interpreter
# is preferred to another python3 earlier on PATH (pyenv, a virtual environment), which may
# lack them; -DPython3_EXECUTABLE=... chooses another.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 3.8 QUIET COMPONENTS Interpreter Development.Module)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python3_FOUND AND pybind11_FOUND)
  set(ENVCRUST_PYTHON_FOUND TRUE)
else()
  set(ENVCRUST_PYTHON_FOUND FALSE)
endif()

# envcrust_add_pytest(NAME DIR TIMEOUT ENVIRONMENT): one ctest (label python) running pytest
# over the tests in DIR with the interpreter found above; ENVIRONMENT is a list of VAR=value.
function(envcrust_add_pytest name dir timeout environment)
  add_test(NAME ${name} COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${dir})
  set_tests_properties(${name} PROPERTIES LABELS python TIMEOUT ${timeout} ENVIRONMENT "${environment}")
endfunction()

# The fast-only configuration (ctest fast_only_configuration; docs/building.md, "Building parts"):
#   cmake -S SRC -B WORK -DFDH_BUILD_VERIFY=OFF -DFDH_BUILD_PYTHON=OFF -DFDH_WITH_PEERS=OFF
#         -DBUILD_TESTING=OFF
# configured with --trace-expand into a file, built (fdh_fast and fdh_cloth alone), and checked
# from CMake's own record: no find_package, find_dependency, pkg_check_modules, find_path,
# find_library or find_program call anywhere (fdhcert's files or the packages' own) names CGAL,
# GMP, GTest, RapidCheck, FCL, Bullet, Google Benchmark, pybind11, Python, PNG, CLI11, fmt or
# nlohmann-json, and the cache holds no <package>_DIR of theirs; Eigen3 and TBB are found. WORK
# is removed afterwards, pass or fail.
#   cmake -DSRC=<source dir> -DWORK=<scratch dir> -DGENERATOR=<gen> [-DCXX=<compiler>]
#         [-DLAUNCHER=<compiler launcher, e.g. ccache>] -P test_fast_only.cmake
foreach(var SRC WORK GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "test_fast_only.cmake needs -D${var}=...")
  endif()
endforeach()
set(unwanted CGAL GMP GTest rapidcheck fcl bullet benchmark pybind11 Python PNG CLI11 fmt
    nlohmann_json)
set(wanted Eigen3 TBB)

function(fail message)
  file(REMOVE_RECURSE ${WORK})
  message(FATAL_ERROR "${message}")
endfunction()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    fail("${what} failed (${status}):\n${out}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(options -DFDH_BUILD_VERIFY=OFF -DFDH_BUILD_PYTHON=OFF -DFDH_WITH_PEERS=OFF
    -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=Release)
if(CXX)
  list(APPEND options -DCMAKE_CXX_COMPILER=${CXX})
endif()
if(LAUNCHER)
  list(APPEND options -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
string(TIMESTAMP start %s)
run("configure" ${CMAKE_COMMAND} -S ${SRC} -B ${WORK} -G ${GENERATOR} ${options}
    --trace-expand --trace-redirect=${WORK}/trace.txt)
run("build" ${CMAKE_COMMAND} --build ${WORK})
string(TIMESTAMP end %s)
foreach(library fdh_fast fdh_cloth)
  file(GLOB_RECURSE built ${WORK}/lib${library}.a)
  if(NOT built)
    fail("lib${library}.a was not built")
  endif()
endforeach()

# One line per searching call in the trace: `<file>(<line>):  find_package(<args> )`.
set(searching find_package find_dependency pkg_check_modules pkg_search_module find_path
    find_library find_program)
string(REPLACE ";" "|" searching "${searching}")
file(STRINGS ${WORK}/trace.txt searches REGEX "\\):  *(${searching})\\(")
file(READ ${WORK}/CMakeCache.txt cache)
foreach(package IN LISTS unwanted)
  string(TOLOWER ${package} lower)
  foreach(line IN LISTS searches)
    string(TOLOWER "${line}" line_lower)
    if(line_lower MATCHES "[( _]${lower}")
      fail("the fast-only configuration searched for ${package}:\n  ${line}")
    endif()
  endforeach()
  if(cache MATCHES "\n${package}_DIR:")
    fail("the fast-only configuration's cache holds ${package}_DIR")
  endif()
endforeach()
foreach(package IN LISTS wanted)
  if(NOT cache MATCHES "\n${package}_DIR:")
    fail("the fast-only configuration never found ${package} (no ${package}_DIR in its cache)")
  endif()
endforeach()
list(LENGTH searches count)
math(EXPR seconds "${end} - ${start}")
message(STATUS "fast-only: configured and built in ${seconds} s; ${count} searching calls, "
               "none for: ${unwanted}")
file(REMOVE_RECURSE ${WORK})

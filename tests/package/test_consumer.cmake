# The installed package, as a user's project meets it (ctest package_consumer):
# `cmake --install` of this build into a fresh prefix, then examples/consumer configured, built
# and run against that prefix alone. Also: the fast library's exported interface names no CGAL.
# With -DPLUGIN=<a plug-in>: the installed fdhcert certifies it from an empty folder, finding
# the installed corpus by itself (issue 24, "certify anywhere").
# With -DPREFIX=<an installed tree> (the unpacked Debian package, test_deb.sh): no install, the
# consumer against that tree.
#   cmake -DBUILD=<build dir> -DSRC=<source dir> -DWORK=<scratch dir> -DGENERATOR=<gen>
#         [-DPLUGIN=<plug-in>] [-DPREFIX=<tree>] -P test_consumer.cmake
foreach(var BUILD SRC WORK GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "test_consumer.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
  message(STATUS "${what}: ok\n${out}")
endfunction()

if(DEFINED PREFIX)
  set(prefix ${PREFIX})
else()
  run("install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
endif()
if(NOT EXISTS ${prefix}/include/fdh/plugin.h)
  message(FATAL_ERROR "the plug-in header fdh/plugin.h is not installed")
endif()
file(GLOB fast_targets_file ${prefix}/lib/cmake/fdhcert/fdhcertFastTargets.cmake
     ${prefix}/lib/*/cmake/fdhcert/fdhcertFastTargets.cmake)
if(NOT fast_targets_file)
  message(FATAL_ERROR "no lib/cmake/fdhcert/fdhcertFastTargets.cmake under ${prefix}")
endif()
file(READ ${fast_targets_file} fast_targets)
if(fast_targets MATCHES "CGAL|gmp")
  message(FATAL_ERROR "fdhcert::fast or fdhcert::cloth names CGAL or GMP in its interface")
endif()
run("configure the consumer" ${CMAKE_COMMAND} -S ${SRC}/examples/consumer -B ${WORK}/consumer
    -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK}/consumer)
run("run the consumer" ${WORK}/consumer/consumer)

# certify from an empty folder, with the installed program and corpus alone. Smaller samples
# than --quick's alone: the point is where the corpus comes from, not the certificate.
if(DEFINED PLUGIN)
  set(empty ${WORK}/empty)
  file(MAKE_DIRECTORY ${empty})
  execute_process(COMMAND ${prefix}/bin/fdhcert certify --quick --plugin ${PLUGIN} --quiet
                          --per-family 20 --soups 3 --peer-cases 30
                  WORKING_DIRECTORY ${empty} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  message(STATUS "certify from an empty folder (${status}):\n${out}")
  file(REAL_PATH ${prefix}/share/fdhcert/corpus corpus)
  if(NOT status EQUAL 0 OR NOT out MATCHES "corpus: ${corpus}\n"
     OR NOT out MATCHES "certified: " OR NOT EXISTS ${empty}/certificate/certificate.md)
    message(FATAL_ERROR "the installed fdhcert did not certify from an empty folder with the "
                        "installed corpus ${corpus}")
  endif()
  # The build folder's program has no installed corpus beside it: certify says where it looked.
  execute_process(COMMAND ${BUILD}/verify/cli/fdhcert certify --quick WORKING_DIRECTORY ${empty}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 2 OR NOT out MATCHES "no corpus folder: looked for ./corpus .* and .*share/fdhcert/corpus")
    message(FATAL_ERROR "certify without a corpus: exit ${status}, not 2 naming where it looked:\n${out}")
  endif()
  message(STATUS "certify without a corpus: ${out}")
endif()
file(REMOVE_RECURSE ${WORK})

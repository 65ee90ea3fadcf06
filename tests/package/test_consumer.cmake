# The installed package, as a user's project meets it (ctest package_consumer):
# `cmake --install` of this build into a fresh prefix, then examples/consumer configured, built
# and run against that prefix alone. Also: the fast library's exported interface names no CGAL.
#   cmake -DBUILD=<build dir> -DSRC=<source dir> -DWORK=<scratch dir> -DGENERATOR=<gen> -P ...
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

run("install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
if(NOT EXISTS ${prefix}/include/fdh/plugin.h)
  message(FATAL_ERROR "the plug-in header fdh/plugin.h is not installed")
endif()
file(READ ${prefix}/lib/cmake/fdhcert/fdhcertFastTargets.cmake fast_targets)
if(fast_targets MATCHES "CGAL|gmp")
  message(FATAL_ERROR "fdhcert::fast or fdhcert::cloth names CGAL or GMP in its interface")
endif()
run("configure the consumer" ${CMAKE_COMMAND} -S ${SRC}/examples/consumer -B ${WORK}/consumer
    -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK}/consumer)
run("run the consumer" ${WORK}/consumer/consumer)
file(REMOVE_RECURSE ${WORK})

# Read by cpack as it starts (CPACK_PROJECT_CONFIG_FILE, cmake/package.cmake): the Debian
# package's Depends gets what dpkg-shlibdeps finds for the ELF files it ships,
# FDH_DEB_ELF_FILES (the program and the Python module, as built: the same libraries as the
# stripped copies in the package).
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(FDH_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT FDH_DPKG_SHLIBDEPS)
  message(FATAL_ERROR "the Debian package needs dpkg-shlibdeps (Debian: dpkg-dev)")
endif()
# dpkg-shlibdeps reads debian/control of its working folder: an empty one, in a folder of its own.
string(RANDOM LENGTH 8 fdh_tag)
set(fdh_dir "${CPACK_PACKAGE_DIRECTORY}/_CPack_Packages/shlibdeps-${fdh_tag}")
file(MAKE_DIRECTORY "${fdh_dir}/debian")
file(WRITE "${fdh_dir}/debian/control" "")
execute_process(COMMAND ${FDH_DPKG_SHLIBDEPS} -O ${FDH_DEB_ELF_FILES}
                WORKING_DIRECTORY "${fdh_dir}" RESULT_VARIABLE fdh_status
                OUTPUT_VARIABLE fdh_out ERROR_VARIABLE fdh_err)
file(REMOVE_RECURSE "${fdh_dir}")
if(NOT fdh_status EQUAL 0 OR NOT fdh_out MATCHES "^shlibs:Depends=([^\n]+)")
  message(FATAL_ERROR "dpkg-shlibdeps ${FDH_DEB_ELF_FILES} failed (${fdh_status}): ${fdh_err}")
endif()
string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", ${CMAKE_MATCH_1}")
message(STATUS "Depends: ${CPACK_DEBIAN_PACKAGE_DEPENDS}")

# The Debian package (docs/package.md): `cpack -G DEB` in a build folder, or `./run package`,
# writes fdhcert_<version>_amd64.deb. One package: the fdhcert program, the static libraries,
# their headers and CMake package, the plug-in header, the Python module (in Debian's
# dist-packages), the manual page and the corpus that certify reads. Every library is static, so
# a runtime/-dev split would leave a runtime package of one program: not worth a second package.
# Depends: what dpkg-shlibdeps finds in the program and the module, and Python and numpy, which
# it cannot see. dpkg-shlibdeps is run on those two files alone, when cpack starts
# (packaging/debian/shlibdeps.cmake): CPack's own CPACK_DEBIAN_PACKAGE_SHLIBDEPS first runs
# `cmake -E env file` once for every packaged file to find them (160 files, most of them the
# corpus), which took 63 s of a 65 s cpack here against 2 s without it.
set(FDH_DEB_MAINTAINER "fdhcert maintainers <maintainers@users.noreply.h-seed-4266a020.example>")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME fdhcert)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${FDH_DEB_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # the program and the module; static libraries keep their symbols
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # fdhcert_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)  # done by shlibdeps.cmake, below
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)  # xz takes several times longer on the static libraries
# The summary, then the extended description (CPack indents its lines by one space).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "exact verification of FDH (k-DOP) cloth collision detection
fdhcert certifies the point-triangle and continuous collision tests of a cloth
simulator, with k-DOP (FDH) trees after Han and Jia 2013, against exact
rational twins: the fdhcert program (certify, classify, fuzz, report, simulate,
audit), its C++ libraries with headers and CMake package, the plug-in header
for certifying other libraries, and the Python module fdhcert.")
get_property(fdh_python_depends GLOBAL PROPERTY FDH_DEB_PYTHON_DEPENDS)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${fdh_python_depends}")
set(FDH_DEB_ELF_FILES "$<TARGET_FILE:fdhcert>;$<TARGET_FILE:fdhcert_python>")
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/CPackShlibdeps.cmake CONTENT
     "set(FDH_DEB_ELF_FILES \"${FDH_DEB_ELF_FILES}\")\ninclude(\"${PROJECT_SOURCE_DIR}/packaging/debian/shlibdeps.cmake\")\n")
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/CPackShlibdeps.cmake)
# find_package(fdhcert) needs Eigen and oneTBB (and CGAL for fdhcert::reference); report's charts
# need gnuplot.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libeigen3-dev, libtbb-dev, gnuplot-nox")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libcgal-dev, libgmp-dev")

# Debian's policy: a copyright file and a changelog (a native package's, gzipped) in
# /usr/share/doc/fdhcert. SOURCE_DATE_EPOCH, when set, fixes the date.
string(TIMESTAMP FDH_DEB_DATE "%a, %d %b %Y %H:%M:%S +0000" UTC)
set(fdh_doc ${PROJECT_BINARY_DIR}/deb-doc)
configure_file(${PROJECT_SOURCE_DIR}/packaging/debian/changelog.in ${fdh_doc}/changelog @ONLY)
execute_process(COMMAND gzip -9 -n -f -k ${fdh_doc}/changelog RESULT_VARIABLE fdh_gzip)
if(NOT fdh_gzip EQUAL 0)
  message(FATAL_ERROR "gzip ${fdh_doc}/changelog failed: ${fdh_gzip}")
endif()
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/copyright ${fdh_doc}/changelog.gz
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
include(CPack)

# The installed CMake package: `cmake --install BUILD --prefix P` puts the libraries, their public
# headers and fdhcertConfig.cmake (with its version file) under P, and
# `find_package(fdhcert)` then gives
#   fdhcert::fast       floating point only (Eigen): k-DOPs, the FDH tree, the point-triangle
#                       and CCD methods
#   fdhcert::cloth      the mass-spring cloth on fast
#   fdhcert::reference  the exact twins (CGAL and GMP, linked privately)
# fast and cloth are one export set that needs Eigen (and oneTBB, for the cloth's threads); reference is a second one, loaded
# when CGAL is found, so that a project using fast never needs (or links) CGAL.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(FDH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fdhcert)
set_target_properties(fdh_fast PROPERTIES EXPORT_NAME fast)
set_target_properties(fdh_cloth PROPERTIES EXPORT_NAME cloth)
set_target_properties(fdh_parallel PROPERTIES EXPORT_NAME parallel)

install(TARGETS fdh_fast fdh_parallel fdh_cloth EXPORT fdhcertFast
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir fast parallel cloth)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(EXPORT fdhcertFast NAMESPACE fdhcert:: FILE fdhcertFastTargets.cmake
        DESTINATION ${FDH_CMAKE_DIR})
# reference and the fdhcert program come with the verification suite (FDH_BUILD_VERIFY).
if(FDH_BUILD_VERIFY)
  set_target_properties(fdh_reference PROPERTIES EXPORT_NAME reference)
  install(TARGETS fdh_reference EXPORT fdhcertReference
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/reference/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT fdhcertReference NAMESPACE fdhcert:: FILE fdhcertReferenceTargets.cmake
          DESTINATION ${FDH_CMAKE_DIR})
  install(TARGETS fdhcert RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # The plug-in ABI (docs/plugins.md): plain C, for users' shared libraries.
  install(FILES ${PROJECT_SOURCE_DIR}/verify/plugin/include/fdh/plugin.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fdh)
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/fdhcertConfig.cmake.in
  ${PROJECT_BINARY_DIR}/fdhcertConfig.cmake INSTALL_DESTINATION ${FDH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/fdhcertConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/fdhcertConfig.cmake
              ${PROJECT_BINARY_DIR}/fdhcertConfigVersion.cmake
        DESTINATION ${FDH_CMAKE_DIR})

# The corpus that `certify` and `report` read, installed as data (issue 24): their --corpus
# default finds it from the program's folder when ./corpus is not there
# (verify/certify/src/corpus_folder.cpp), so an installed fdhcert certifies from any folder.
if(FDH_BUILD_VERIFY)
  set(FDH_CORPUS_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/fdhcert/corpus)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/corpus/ DESTINATION ${FDH_CORPUS_INSTALL_DIR})
  if(IS_ABSOLUTE ${CMAKE_INSTALL_BINDIR} OR IS_ABSOLUTE ${FDH_CORPUS_INSTALL_DIR})
    set(fdh_corpus_from_bindir ${CMAKE_INSTALL_FULL_DATADIR}/fdhcert/corpus)
  else()
    file(RELATIVE_PATH fdh_corpus_from_bindir /${CMAKE_INSTALL_BINDIR} /${FDH_CORPUS_INSTALL_DIR})
  endif()
  target_compile_definitions(fdh_certify PRIVATE FDH_CORPUS_FROM_BINDIR="${fdh_corpus_from_bindir}")
  if(NOT FDH_FUZZERS)
    include(man_page)
  endif()
endif()

# The manual page fdhcert(1): packaging/man_page.py runs the built fdhcert's --help and
# `help COMMAND` for every command it lists and turns them into one page (a section per
# command), so that page and program cannot drift. Built with the program (target fdhcert_man),
# gzipped as Debian installs manual pages, installed into share/man/man1.
# Any python3 does (the script uses the standard library alone); Debian's first, as for the module.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter)
if(NOT Python3_Interpreter_FOUND)
  message(STATUS "fdhcert(1): no python3, no manual page")
  return()
endif()
set(FDH_MAN_PAGE ${PROJECT_BINARY_DIR}/man/fdhcert.1)
add_custom_command(OUTPUT ${FDH_MAN_PAGE} ${FDH_MAN_PAGE}.gz
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/packaging/man_page.py
          $<TARGET_FILE:fdhcert> ${PROJECT_VERSION} ${FDH_MAN_PAGE}
  # -n: no name or time stamp inside, so the same page gives the same bytes.
  COMMAND gzip -9 -n -f -k ${FDH_MAN_PAGE}
  DEPENDS fdhcert ${PROJECT_SOURCE_DIR}/packaging/man_page.py
  COMMENT "Writing the manual page fdhcert(1)" VERBATIM)
add_custom_target(fdhcert_man ALL DEPENDS ${FDH_MAN_PAGE})
install(FILES ${FDH_MAN_PAGE}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# fdh_find_global_package(<package> [find_package arguments...])
# find_package in the folder of the package's user, with the imported targets it makes visible to
# the whole build. A static library that links a package privately still hands it to the final
# link of every program that uses the library, in other folders (reference's CGAL, for one, is
# linked into fdhcert, the tests and the Python module), and an imported target is otherwise seen
# only in the folder that found it and below.
function(fdh_find_global_package package)
  get_directory_property(before IMPORTED_TARGETS)
  find_package(${package} ${ARGN})
  get_directory_property(after IMPORTED_TARGETS)
  foreach(target IN LISTS after)
    if(NOT target IN_LIST before)
      set_property(TARGET ${target} PROPERTY IMPORTED_GLOBAL TRUE)
    endif()
  endforeach()
endfunction()

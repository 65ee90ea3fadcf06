#include "fdh/exact/versions.hpp"

#include <CGAL/version.h>
#include <gmp.h>

namespace fdh::exact {

std::string cgal_library_version() {
  return CGAL_VERSION_STR;
}
std::string gmp_library_version() {
  return gmp_version;
}

}  // namespace fdh::exact

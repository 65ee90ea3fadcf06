// The versions of the exact arithmetic behind the reference, for certificates.
#pragma once

#include <string>

namespace fdh::exact {

std::string cgal_library_version();
std::string gmp_library_version();

}  // namespace fdh::exact

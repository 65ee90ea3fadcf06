// Where the tests' data files are (tests/data/ in the source tree).
#pragma once

#include <string>

namespace fdh {

inline const std::string kData = FDH_SOURCE_DIR "/tests/data/";

}  // namespace fdh

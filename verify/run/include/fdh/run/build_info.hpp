// Moved to fdh/os/build_info.hpp (issue 29). Kept only for the files another change is moving
// out of verify/run/ (certify's scene runs); it goes with this folder.
#pragma once

#include "fdh/os/build_info.hpp"

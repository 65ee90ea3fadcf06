// Moved to fdh/io/json_text.hpp (issue 29). Kept only for the files another change is moving
// out of verify/run/ (the audit and scene outputs); it goes with this folder.
#pragma once

#include "fdh/io/json_text.hpp"

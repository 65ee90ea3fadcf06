// The registry's two halves, each in the file of its constructions. Private to fdh_gen.
#pragma once

#include <vector>

#include "fdh/gen/families.hpp"

namespace fdh::verify {

std::vector<Family> static_families();  // static vertex-face: static_families.cpp
std::vector<Family> moving_families();  // moving vertex-face and edge-edge: moving_families.cpp
std::vector<Family> min_distance_families();  // at δ > 0: delta_families.cpp

}  // namespace fdh::verify

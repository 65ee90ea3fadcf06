// The picture of a violation (DIR/first-violation.png): a close-up that frames the offending
// primitives, the violation's triangles in blue drawn over whatever hides them, and the whole
// frame as an inset; seen with the data's up axis up.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/audit/auditor.hpp"

namespace fdh::verify {

// The picture's up axis: 0, 1 or 2 (x, y, z).
// From the data: the axis along which the cloth's centroid moved most from `start` (frame 0's
// cloth) to `now` (gravity pulls down), else, when it hardly moved, the axis of the frame's
// smallest extent (a sheet lies flat).
int up_axis_of(const std::vector<Vec3>& start, const std::vector<Vec3>& now,
               const std::vector<Vec3>& obstacle);

// PNG bytes: the cloth and obstacle positions of the frame that holds `v`, with `up` (0, 1, 2)
// drawn up.
std::string violation_picture(const std::vector<Vec3>& cloth, const std::vector<Vec3>& obstacle,
                              const audit::Violation& v, const audit::Topology& t, int up);

}  // namespace fdh::verify

// The picture of a violation (DIR/first-violation.png): its frame rendered as `simulate --png`
// renders, the violation's triangles in blue.
#pragma once

#include <string>
#include <vector>

#include "fdh/audit/auditor.hpp"

namespace fdh::verify {

// PNG bytes: the cloth and obstacle positions of the frame that holds `v`.
std::string violation_picture(const std::vector<Vec3>& cloth, const std::vector<Vec3>& obstacle,
                              const audit::Violation& v, const audit::Topology& t);

}  // namespace fdh::verify

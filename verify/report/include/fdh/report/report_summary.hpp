// What a reader wants first from `fdhcert report`: the few lines `./run verify` prints
// (report --summary) and the report's "At a glance" tables, both from the Report's structs.
#pragma once

#include <string>

#include "fdh/report/report_document.hpp"

namespace fdh::verify {

// Four lines: certified or not with the checks, violations and inputs; the exact promises with
// their query counts; the metamorphic verdict changes; the peers' boxes (counted, not held).
std::string report_summary(const Report& report);

// Markdown: one row per method with its promise and, over the static and over the moving
// families, its FP and FN counts and median ns per query; then one row per bounding-volume
// method (the own k-DOPs and the peers' boxes) with its containment and overlap violations.
std::string glance_markdown(const Report& report);

}  // namespace fdh::verify

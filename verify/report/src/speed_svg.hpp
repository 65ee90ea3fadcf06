// The speed-against-accuracy chart as SVG written here (not by gnuplot), for the HTML report:
// one circle per method and family, each with a <title> (method, family, FP and FN rates, ns
// per query) that a browser shows on hover, and data-* attributes for the page's own script.
#pragma once

#include <string>
#include <vector>

#include "fdh/report/measurements.hpp"

namespace fdh::verify {

// One panel per kind of family ("static", then "moving") that has rows: x = ns per query (log),
// y = FP + FN rate; colour = method (the colours of the gnuplot chart), key beside the panel.
std::string speed_accuracy_svg(const std::vector<SpeedAccuracyRow>& rows);

}  // namespace fdh::verify

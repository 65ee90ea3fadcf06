// The report's charts, drawn by gnuplot (Debian's gnuplot-nox) from the CSVs in <dir>/data:
// speed_accuracy, stability and kdop_k, each as .png (for people) and .svg (for the docs).
#pragma once

#include <string>

namespace fdh::verify {

// Throws std::runtime_error when gnuplot is missing or fails.
void draw_charts(const std::string& dir);

// <dir>/table1.png and .svg from <dir>/data/table1.csv (fdhcert table1 --out).
void draw_table1_chart(const std::string& dir);

}  // namespace fdh::verify

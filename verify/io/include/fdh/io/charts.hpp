// Charts drawn by gnuplot (Debian's gnuplot-nox), each as .png (for people) and .svg (for the
// docs). The caller writes the data files and the plot commands; this file quotes, runs
// gnuplot without a shell and reports its failure.
#pragma once

#include <string>
#include <string_view>

namespace fdh::verify {

// `s` as a gnuplot string literal: in single quotes, a quote doubled, nothing else
// interpreted. Throws std::invalid_argument for a line break, which no gnuplot literal holds.
std::string gnuplot_quote(std::string_view s);

// One chart: `commands` plot from data files (their paths quoted with gnuplot_quote, relative
// to the chart's folder, or absolute) after `set datafile separator ','` and `set grid`; the
// terminal and the output are set here. gnuplot runs in the chart's folder, so the folder's
// name never enters the script.
struct Chart {
  std::string stem;  // the chart goes to <stem>.png and <stem>.svg
  int width = 900, height = 600;
  std::string commands;
};

// Draws the chart twice, as PNG (pngcairo) and as SVG. gnuplot is started with an argument
// list (fork and execvp, no shell), reads its script from a temporary file, draws into
// temporary files beside the chart that are renamed into place only when it succeeded, and is
// killed if fdhcert dies first (PR_SET_PDEATHSIG). Throws std::runtime_error when gnuplot is
// missing or fails (its messages go to stderr) or a chart path is not a regular file; the old
// charts are then left as they were.
void draw_chart(const Chart& chart);

}  // namespace fdh::verify

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
// list (fork and execvp, no shell), reads its script from a temporary file, and draws into a
// folder of its own beside the chart (DIR/NAME.tmp.<pid>.XXXXXX: mkdtemp, mode 0700, so no
// link can be planted at a name it opens). Both drawings are checked whole (the PNG's chunks
// to IEND, the SVG to `</svg>`) before either is renamed into place. gnuplot is killed if
// fdhcert dies first (PR_SET_PDEATHSIG); what a killed run left is removed by the next
// (fdh/os/temporaries.hpp). Throws std::runtime_error when gnuplot is missing, fails or draws a
// cut chart ("gnuplot failed drawing DIR/NAME.png: No space left on device": gnuplot ignores its
// write errors, so a cut chart's reason is found by a probe write beside it), or a chart path
// is not a regular file; the old charts are then left as they were, byte for byte.
void draw_chart(const Chart& chart);

}  // namespace fdh::verify

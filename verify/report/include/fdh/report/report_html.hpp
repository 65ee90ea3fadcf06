// The report as one self-contained HTML page (DIR/index.html): report.md's text and tables, the
// charts inline as SVG (read from DIR, drawn before), no network and no script from outside.
// The speed-against-accuracy chart is drawn here (speed_svg.hpp) so that hovering a point names
// its method, family, FP and FN rates and ns per query; every `code` span or word of the text
// that names an existing file becomes a link to it, relative to DIR (the counterexamples).
#pragma once

#include <string>

#include "fdh/report/report_document.hpp"

namespace fdh::verify {

// The page for `report`, written into `dir` (whose *.svg charts it inlines: the report's
// options.files_dir()); links are relative to options.out_dir, where the page is published.
// Throws std::runtime_error if a chart cannot be read.
std::string report_html(const Report& report, const std::string& dir);

}  // namespace fdh::verify

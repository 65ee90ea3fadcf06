#include "fdh/report/report_html.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "markdown_html.hpp"
#include "speed_svg.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

const char* const kStyle =
    R"(body{font-family:sans-serif;margin:0 auto;max-width:1200px;padding:1em;color:#222}
table{border-collapse:collapse;margin:0.5em 0 1em;font-size:0.9em}
td,th{border:1px solid #ccc;padding:2px 6px;text-align:left;vertical-align:top}
th{background:#f0f0f0}
figure{margin:1em 0}
figure svg{width:100%;height:auto}
code{font-size:0.95em}
pre{background:#f6f6f6;padding:0.5em;overflow-x:auto}
#tip{position:fixed;right:1em;bottom:1em;background:#fffbe6;border:1px solid #999;padding:4px 8px;
font-size:0.9em;display:none}
circle.point:hover{stroke-width:2;stroke:#000})";

// Fills #tip with the hovered point's data-* attributes (each point also has a <title>).
const char* const kScript = R"(document.addEventListener('DOMContentLoaded', function () {
  var tip = document.getElementById('tip');
  document.querySelectorAll('circle.point').forEach(function (c) {
    c.addEventListener('mouseenter', function () {
      var d = c.dataset;
      tip.textContent = d.method + ' on ' + d.family + ': FP rate ' + d.fp + ', FN rate ' +
                        d.fn + ', ' + d.ns + ' ns per query';
      tip.style.display = 'block';
    });
    c.addEventListener('mouseleave', function () { tip.style.display = 'none'; });
  });
});)";

std::string read_whole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::runtime_error(file.string() + ": cannot read the chart for index.html");
  return text.str();
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
}

// A gnuplot SVG for inlining: from <svg on (no XML prologue), its ids prefixed so that the
// charts of one page keep theirs apart (gnuplot names its point shapes alike in every file), its
// own title "Gnuplot" replaced by `alt`.
std::string inline_svg(std::string svg, const std::string& prefix, const std::string& alt) {
  const std::size_t open = svg.find("<svg");
  if (open == std::string::npos) return "";
  svg.erase(0, open);
  for (const char q : {'"', '\''}) {
    const std::string quote(1, q);
    replace_all(svg, "id=" + quote, "id=" + quote + prefix);
    replace_all(svg, "href=" + quote + "#", "href=" + quote + "#" + prefix);
  }
  replace_all(svg, "url(#", "url(#" + prefix);
  replace_all(svg, "<title>Gnuplot</title>", "<title>" + html_escape(alt) + "</title>");
  return svg;
}

}  // namespace

std::string report_html(const Report& report, const std::string& dir) {
  const fs::path root(dir);
  int charts = 0;
  MarkdownHooks hooks;
  hooks.image = [&](const std::string& alt, const std::string& src) {
    const std::string svg =
        src == "speed_accuracy.svg"
            ? speed_accuracy_svg(report.measurements.speed)
            : inline_svg(read_whole(root / src), fmt::format("c{}-", ++charts), alt);
    return fmt::format(
        "<figure>\n{}<figcaption>{} (<a href=\"{}\">SVG</a>)</figcaption></figure>\n", svg,
        html_escape(alt), html_escape(src));
  };
  // A link to a file of this output, named by the output's folder (out_dir), is looked for
  // where the file is being written (`dir`: a staged output's private folder); any other where
  // it is.
  const fs::path named(report.certificate.options.out_dir);
  hooks.link = [&](const std::string& text) -> std::string {
    if (text.empty() || text.find('/') == std::string::npos) return "";
    std::error_code ec;
    const fs::path rel = fs::relative(fs::absolute(text), fs::absolute(named), ec);
    if (ec || rel.empty()) return "";
    const bool inside = *rel.begin() != "..";
    if (!fs::is_regular_file(inside ? root / rel : fs::path(text), ec)) return "";
    return rel.generic_string();
  };
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>fdhcert verification report</title>\n<style>\n{}\n</style>\n</head>\n<body>\n"
      "{}<div id=\"tip\"></div>\n<script>\n{}\n</script>\n</body>\n</html>\n",
      kStyle, markdown_html(report_markdown(report), hooks), kScript);
}

}  // namespace fdh::verify

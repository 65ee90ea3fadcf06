#include "markdown_html.hpp"

#include <fmt/format.h>

#include <sstream>
#include <vector>

namespace fdh::verify {
namespace {

bool starts_with(std::string_view s, std::string_view p) {
  return s.substr(0, p.size()) == p;
}

std::string linked(const MarkdownHooks& hooks, const std::string& text, const std::string& html) {
  const std::string href = hooks.link ? hooks.link(text) : "";
  return href.empty() ? html : fmt::format("<a href=\"{}\">{}</a>", html_escape(href), html);
}

// Plain text: escaped, each word that names a file linked (trailing punctuation kept outside).
std::string text_html(std::string_view s, const MarkdownHooks& hooks) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t end = std::min(s.find(' ', i), s.size());
    std::string_view word = s.substr(i, end - i);
    std::size_t cut = word.size();
    while (cut > 0 && std::string_view(",.;:)").find(word[cut - 1]) != std::string_view::npos)
      --cut;
    const std::string core(word.substr(0, cut));
    out += linked(hooks, core, html_escape(core)) + html_escape(word.substr(cut));
    if (end < s.size()) out += ' ';
    i = end + 1;
  }
  return out;
}

// `code` and **bold** spans; the rest as text_html.
std::string inline_html(std::string_view s, const MarkdownHooks& hooks) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t tick = s.find('`', i), bold = s.find("**", i);
    const std::size_t next = std::min(tick, bold);
    if (next == std::string_view::npos) break;
    out += text_html(s.substr(i, next - i), hooks);
    const bool is_code = next == tick;
    const std::size_t width = is_code ? 1 : 2;
    const std::size_t close = s.find(is_code ? "`" : "**", next + width);
    if (close == std::string_view::npos) {  // unpaired: literal
      out += html_escape(s.substr(next, width));
      i = next + width;
      continue;
    }
    const std::string inner(s.substr(next + width, close - next - width));
    out += is_code ? linked(hooks, inner, "<code>" + html_escape(inner) + "</code>")
                   : "<strong>" + inline_html(inner, hooks) + "</strong>";
    i = close + width;
  }
  if (i < s.size()) out += text_html(s.substr(i), hooks);
  return out;
}

// The cells of a table row "| a | b |" (a cell holds no '|' in fdhcert's Markdown).
std::vector<std::string> cells(std::string_view row) {
  std::vector<std::string> out;
  std::string_view s = row.substr(1);
  if (!s.empty() && s.back() == '|') s.remove_suffix(1);
  for (std::size_t i = 0; i <= s.size();) {
    const std::size_t bar = std::min(s.find('|', i), s.size());
    std::string_view c = s.substr(i, bar - i);
    while (!c.empty() && c.front() == ' ') c.remove_prefix(1);
    while (!c.empty() && c.back() == ' ') c.remove_suffix(1);
    out.emplace_back(c);
    i = bar + 1;
  }
  return out;
}

std::string table_html(const std::vector<std::string>& rows, const MarkdownHooks& hooks) {
  std::string out = "<table>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (r == 1 && starts_with(rows[r], "|-")) continue;  // the alignment row
    const char* tag = r == 0 ? "th" : "td";
    out += "<tr>";
    for (const std::string& c : cells(rows[r]))
      out += fmt::format("<{0}>{1}</{0}>", tag, inline_html(c, hooks));
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

// An image line ![alt](src), or false.
bool image_line(const std::string& line, std::string& alt, std::string& src) {
  const std::size_t mid = line.find("](");
  if (!starts_with(line, "![") || mid == std::string::npos || line.back() != ')') return false;
  alt = line.substr(2, mid - 2);
  src = line.substr(mid + 2, line.size() - mid - 3);
  return true;
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  for (const char ch : text) switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  return out;
}

std::string markdown_html(std::string_view markdown, const MarkdownHooks& hooks) {
  std::istringstream in{std::string(markdown)};
  std::string out, line, alt, src;
  std::vector<std::string> block;  // the lines of the paragraph or table being read
  bool table = false;
  const auto flush = [&] {
    if (!block.empty()) {
      out += table
                 ? table_html(block, hooks)
                 : "<p>" + inline_html(fmt::format("{}", fmt::join(block, " ")), hooks) + "</p>\n";
    }
    block.clear();
    table = false;
  };
  while (std::getline(in, line)) {
    if (starts_with(line, "```")) {
      flush();
      out += "<pre>";
      while (std::getline(in, line) && !starts_with(line, "```")) out += html_escape(line) + "\n";
      out += "</pre>\n";
    } else if (line.empty()) {
      flush();
    } else if (line[0] == '#') {
      flush();
      const std::size_t level = std::min(line.find_first_not_of('#'), std::size_t(6));
      out += fmt::format(
          "<h{0}>{1}</h{0}>\n", level,
          inline_html(std::string_view(line).substr(std::min(level + 1, line.size())), hooks));
    } else if (image_line(line, alt, src)) {
      flush();
      out += hooks.image ? hooks.image(alt, src)
                         : fmt::format("<p><img alt=\"{}\" src=\"{}\"></p>\n", html_escape(alt),
                                       html_escape(src));
    } else {
      if (!block.empty() && table != (line[0] == '|')) flush();
      table = line[0] == '|';
      block.push_back(line);
    }
  }
  flush();
  return out;
}

}  // namespace fdh::verify

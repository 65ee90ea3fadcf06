// The Markdown that fdhcert writes (report.md, certificate.md) as HTML: headings, paragraphs,
// pipe tables, images alone on a line, fenced code, and inline `code` and **bold**. Only that
// subset, which is all the report uses; anything else is a paragraph of escaped text.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace fdh::verify {

struct MarkdownHooks {
  // The HTML for an image line ![alt](src); empty: an <img>.
  std::function<std::string(const std::string& alt, const std::string& src)> image;
  // Where a `code` span or a word of text links to (it names a file), or "" for no link.
  std::function<std::string(const std::string& text)> link;
};

// `text` with &, <, > and " escaped.
std::string html_escape(std::string_view text);

std::string markdown_html(std::string_view markdown, const MarkdownHooks& hooks = {});

}  // namespace fdh::verify

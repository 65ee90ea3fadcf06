// A text line's words: the OBJ and PLY readers split their lines the same way.
#pragma once

#include <string_view>
#include <vector>

namespace fdh::verify {

// The words of `line`, separated by spaces and tabs (views into `line`).
std::vector<std::string_view> line_words(std::string_view line);

}  // namespace fdh::verify

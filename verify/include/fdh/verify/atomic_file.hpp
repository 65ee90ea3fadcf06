// Files are written whole: a temporary file beside the target, then a rename. A reader (or a
// crash) never sees half a file.
#pragma once

#include <string>

namespace fdh::verify {

// Throws std::runtime_error naming the path when the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fdh::verify

// Stored cases: one query per native file, named by a hash of its coordinates so that the same
// case found twice (by two threads, two shards, or a resumed run) is one file.
#pragma once

#include <string>
#include <vector>

#include "fdh/io/query_record.hpp"

namespace fdh::verify {

// 16 hex digits (FNV-1a over the kind, the 24 coordinates' bits and, when not 0, δ's bits).
std::string case_hash(const Query& q);

// `# comment` lines, then the record as a native line (hex-float, truth included).
std::string case_file_text(const QueryRecord& r, const std::vector<std::string>& comments);

// The query files under `path`: the file itself, or every *.vf below a folder, sorted.
// Anything else (a FIFO, a device) is returned as given, for the reader to take or refuse.
// Throws InputError for a path that does not exist or a folder that cannot be listed.
std::vector<std::string> list_query_files(const std::string& path);

// The regular files named *<extension> below the folder `dir`, sorted. Throws InputError when
// the folder cannot be listed.
std::vector<std::string> files_below(const std::string& dir, const std::string& extension);

}  // namespace fdh::verify

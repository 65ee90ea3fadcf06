// Query files: the native text format and the CCD benchmark's CSV (docs/formats.md), read within
// the bounds of docs/limits.md.
#pragma once

#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fdh/io/query_record.hpp"

namespace fdh::verify {

// A text input read line by line within the bounds of docs/limits.md: the file's size
// (FDH_MAX_FILE_BYTES) and each line's length (FDH_MAX_LINE_BYTES). A folder is refused; a
// FIFO or a character device is read as a stream, the same bounds counting as it goes (so
// /dev/zero stops at its first line's bound). Throws InputError.
class InputFile {
 public:
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // The next line without its '\n' and a final '\r'; false at the end of the file.
  bool next(std::string& line);
  // The number of the line last read (1-based).
  long line() const { return line_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
  long line_ = 0;
  long long bytes_ = 0, max_line_ = 0, max_bytes_ = 0;
};

// Native: `vf|ee <id> <24 numbers> [truth]` per line, `#` comments, and `min-distance D` lines:
// the minimum separation δ (Query::min_distance) of the queries after it, 0 before the first.
// Throws InputError.
std::vector<QueryRecord> read_native(const std::string& path);

// Benchmark CSV: 8 rows per query of `xn,xd,yn,yd,zn,zd,truth`. Every rational must be exactly a
// double. Throws InputError.
std::vector<QueryRecord> read_benchmark_csv(const std::string& path, QueryKind kind);

// The kind a CSV's folder gives it: its parent folder named exactly `vertex-face` or
// `edge-edge`, else none.
std::optional<QueryKind> kind_from_folder(const std::string& path);

// By extension: .csv is the benchmark format, anything else native. A CSV's kind comes from its
// folder (kind_from_folder), else from `kind`; a folder and a `kind` that disagree, or neither,
// is an InputError.
std::vector<QueryRecord> read_query_file(const std::string& path,
                                         std::optional<QueryKind> kind = std::nullopt);

// One native line, coordinates in hex-float so that reading it back gives the same doubles.
// `min_distance` is the δ the stream is at (0 where it starts): a `min-distance D` line (D in
// hex-float) comes first when the query's δ differs from it, and it is set to the query's.
void write_native(std::ostream& os, const QueryRecord& r, double& min_distance);
// The same for a stream that starts here (a case file, a line of a message): the
// `min-distance` line only when the query's δ is not 0. A stream of several records mixing
// δ values takes the form above.
void write_native(std::ostream& os, const QueryRecord& r);

// Parses one number of the native format: decimal (correctly rounded) or hex-float, finite.
// Returns nullopt and sets `why` (the token quoted, see quote()) when it is not one.
std::optional<double> parse_double(const std::string& token, std::string& why);
// A minimum distance δ as the native format and the command lines take it: parse_double's
// number, not negative (-0 is 0).
std::optional<double> parse_min_distance(const std::string& token, std::string& why);

}  // namespace fdh::verify

// Query files: the native text format and the CCD benchmark's CSV (docs/formats.md).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fdh/query.hpp"

namespace fdh::verify {

// Native: `vf|ee <id> <24 numbers> [truth]` per line, `#` comments. Throws InputError.
std::vector<Query> read_native(const std::string& path);

// Benchmark CSV: 8 rows per query of `xn,xd,yn,yd,zn,zd,truth`. Every rational must be exactly a
// double. Throws InputError.
std::vector<Query> read_benchmark_csv(const std::string& path, QueryKind kind);

// By extension: .csv is the benchmark format, anything else native. A CSV's kind is `kind` if
// given, else taken from a `vertex-face` or `edge-edge` folder in its path.
std::vector<Query> read_query_file(const std::string& path,
                                   std::optional<QueryKind> kind = std::nullopt);

// One native line, coordinates in hex-float so that reading it back gives the same doubles.
void write_native(std::ostream& os, const Query& q);

// Parses one number of the native format: decimal (correctly rounded) or hex-float, finite.
// Returns nullopt and sets `why` when it is not one.
std::optional<double> parse_double(const std::string& token, std::string& why);

}  // namespace fdh::verify

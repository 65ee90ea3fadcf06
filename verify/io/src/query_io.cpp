#include "fdh/io/query_io.hpp"

#include <gmpxx.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "fdh/io/input_error.hpp"

namespace fdh::verify {
namespace {

std::ifstream open_or_throw(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  return in;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  std::istringstream is(s);
  if (sep == ' ') {
    while (is >> cur) parts.push_back(cur);
  } else {
    while (std::getline(is, cur, sep)) parts.push_back(cur);
    if (!s.empty() && s.back() == sep) parts.push_back("");
  }
  return parts;
}

void strip_cr(std::string& line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
}

int parse_truth(const std::string& tok, const std::string& path, int line) {
  if (tok == "0") return 0;
  if (tok == "1") return 1;
  throw InputError(path, line, "truth must be 0 or 1, not '" + tok + "'");
}

}  // namespace

std::optional<double> parse_double(const std::string& token, std::string& why) {
  const char* s = token.c_str();
  // strtod also takes "nan", "inf" and "infinity"; the format does not.
  for (const char* p = s; *p; ++p)
    if (*p == 'n' || *p == 'N' || *p == 'i' || *p == 'I') {
      why = "'" + token + "' is not a finite number";
      return std::nullopt;
    }
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);  // glibc: correctly rounded, decimal and hex-float
  if (end == s || *end != '\0') {
    why = "'" + token + "' is not a number";
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    why = "'" + token + "' is outside the range of a double";
    return std::nullopt;
  }
  return v;
}

std::vector<Query> read_native(const std::string& path) {
  std::ifstream in = open_or_throw(path);
  std::vector<Query> out;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    strip_cr(line);
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    const std::vector<std::string> tok = split(line, ' ');
    if (tok.empty()) continue;
    Query q;
    if (tok[0] == "vf") {
      q.kind = QueryKind::VertexFace;
    } else if (tok[0] == "ee") {
      q.kind = QueryKind::EdgeEdge;
    } else {
      throw InputError(path, lineno, "a query line starts with 'vf' or 'ee', not '" + tok[0] + "'");
    }
    if (tok.size() != 26 && tok.size() != 27)
      throw InputError(path, lineno,
                       "expected '" + tok[0] + " <id> <24 numbers> [truth]', found " +
                           std::to_string(tok.size() < 2 ? 0 : tok.size() - 2) +
                           " fields after the id");
    q.id = tok[1];
    for (int i = 0; i < 24; ++i) {
      std::string why;
      const auto v = parse_double(tok[2 + i], why);
      if (!v) throw InputError(path, lineno, "number " + std::to_string(i + 1) + ": " + why);
      double* xyz[3] = {&q.x[i / 3].x, &q.x[i / 3].y, &q.x[i / 3].z};
      *xyz[i % 3] = *v;
    }
    if (tok.size() == 27) q.truth = parse_truth(tok[26], path, lineno);
    q.file = path;
    q.line = lineno;
    out.push_back(q);
  }
  return out;
}

std::vector<Query> read_benchmark_csv(const std::string& path, QueryKind kind) {
  std::ifstream in = open_or_throw(path);
  std::vector<Query> out;
  std::string line;
  Query q;
  int row = 0;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    strip_cr(line);
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> col = split(line, ',');
    if (col.size() != 7)
      throw InputError(path, lineno,
                       "expected 7 comma-separated integers, found " + std::to_string(col.size()));
    if (row == 0) {
      q = Query{};
      q.kind = kind;
      q.file = path;
      q.line = lineno;
      q.id = std::to_string(out.size());
    }
    double xyz[3];
    for (int c = 0; c < 3; ++c) {
      mpz_class num, den;
      if (num.set_str(col[2 * c], 10) != 0 || den.set_str(col[2 * c + 1], 10) != 0)
        throw InputError(path, lineno,
                         "'" + col[2 * c] + "/" + col[2 * c + 1] + "' is not a ratio of integers");
      if (den == 0) throw InputError(path, lineno, "zero denominator");
      mpq_class v(num, den);
      v.canonicalize();
      const double d = v.get_d();  // truncates; exact iff the value is a double
      if (!std::isfinite(d) || mpq_class(d) != v)
        throw InputError(path, lineno,
                         "'" + col[2 * c] + "/" + col[2 * c + 1] + "' is not exactly a double");
      xyz[c] = d;
    }
    q.x[row] = Vec3{xyz[0], xyz[1], xyz[2]};
    const int truth = parse_truth(col[6], path, lineno);
    if (row > 0 && truth != q.truth)
      throw InputError(path, lineno, "the truth column differs within one query");
    q.truth = truth;
    if (++row == 8) {
      out.push_back(q);
      row = 0;
    }
  }
  if (row != 0)
    throw InputError(path, lineno,
                     "the file ends inside a query (" + std::to_string(row) + " of 8 rows)");
  return out;
}

std::vector<Query> read_query_file(const std::string& path, std::optional<QueryKind> kind) {
  const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  if (!csv) return read_native(path);
  if (!kind) {
    if (path.find("vertex-face") != std::string::npos) kind = QueryKind::VertexFace;
    if (path.find("edge-edge") != std::string::npos) kind = QueryKind::EdgeEdge;
  }
  if (!kind)
    throw InputError(path, 0,
                     "cannot tell vertex-face from edge-edge: the path names neither folder; "
                     "pass --kind vf or --kind ee");
  return read_benchmark_csv(path, *kind);
}

void write_native(std::ostream& os, const Query& q) {
  os << (q.kind == QueryKind::VertexFace ? "vf " : "ee ") << q.id;
  char buf[64];
  for (const Vec3& p : q.x)
    for (int c = 0; c < 3; ++c) {
      std::snprintf(buf, sizeof buf, " %a", p[c]);
      os << buf;
    }
  if (q.has_truth()) os << ' ' << q.truth;
  os << '\n';
}

}  // namespace fdh::verify

#include "fdh/io/query_io.hpp"

#include <gmpxx.h>
#include <locale.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>
#include <sstream>

#include "fdh/io/input_error.hpp"

namespace fdh::verify {
namespace {

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

Truth parse_truth(const std::string& tok, const std::string& path, long line) {
  if (tok == "0") return Truth::No;
  if (tok == "1") return Truth::Yes;
  throw InputError(path, line, "truth must be 0 or 1, not " + quote(tok));
}

bool has_control_byte(const std::string& s) {
  for (const char ch : s)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) return true;
  return false;
}

// The next query would pass FDH_MAX_QUERIES.
void check_query_count(std::size_t have, long long max, const InputFile& in) {
  if (static_cast<long long>(have) >= max)
    throw InputError(in.path(), in.line(),
                     "more than " + std::to_string(max) + " queries in one file; " +
                         bound_text(kMaxQueries, max));
}

[[noreturn]] void out_of_memory(const InputFile& in, std::size_t queries) {
  throw InputError(in.path(), in.line(),
                   "out of memory after " + std::to_string(queries) +
                       " queries; split the file (docs/limits.md)");
}

// A CSV field as an integer: an optional sign and decimal digits, with blanks around it allowed
// and none inside it (GMP alone would read "1 2" as 12).
bool parse_integer(const std::string& field, mpz_class& out) {
  const std::size_t b = field.find_first_not_of(" \t");
  if (b == std::string::npos) return false;
  const std::size_t e = field.find_last_not_of(" \t") + 1;
  std::size_t i = b;
  if (field[i] == '-' || field[i] == '+') ++i;
  if (i == e) return false;
  for (std::size_t j = i; j < e; ++j)
    if (field[j] < '0' || field[j] > '9') return false;
  // GMP takes no '+'.
  const std::string digits = (field[b] == '-' ? "-" : "") + field.substr(i, e - i);
  return out.set_str(digits, 10) == 0;
}

std::string trimmed(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") + 1 - b);
}

}  // namespace

InputFile::InputFile(const std::string& path)
    : path_(path), max_line_(bound_value(kMaxLineBytes)), max_bytes_(bound_value(kMaxFileBytes)) {
  f_ = std::fopen(path.c_str(), "rb");
  if (!f_) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  struct stat st;
  if (::fstat(::fileno(f_), &st) != 0) {
    const int err = errno;
    std::fclose(f_);
    throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(err));
  }
  if (S_ISDIR(st.st_mode)) {
    std::fclose(f_);
    throw InputError(path, 0, "is a folder, not a file");
  }
  if (S_ISREG(st.st_mode) && st.st_size > max_bytes_) {
    std::fclose(f_);
    throw InputError(path, 0,
                     "the file has " + std::to_string(static_cast<long long>(st.st_size)) +
                         " bytes, more than " + std::to_string(max_bytes_) + "; " +
                         bound_text(kMaxFileBytes, max_bytes_));
  }
}

InputFile::~InputFile() {
  if (f_) std::fclose(f_);
}

bool InputFile::next(std::string& line) {
  line.clear();
  bool any = false;
  for (int c; (c = getc_unlocked(f_)) != EOF;) {
    any = true;
    if (++bytes_ > max_bytes_)
      throw InputError(path_, line_ + 1,
                       "the input passes " + std::to_string(max_bytes_) + " bytes; " +
                           bound_text(kMaxFileBytes, max_bytes_));
    if (c == '\n') break;
    if (static_cast<long long>(line.size()) >= max_line_)
      throw InputError(path_, line_ + 1,
                       "the line is longer than " + std::to_string(max_line_) + " bytes; " +
                           bound_text(kMaxLineBytes, max_line_));
    line.push_back(static_cast<char>(c));
  }
  if (std::ferror(f_))
    throw InputError(path_, line_ + 1, std::string("read error: ") + std::strerror(errno));
  if (!any) return false;
  if (line_ == INT_MAX) throw InputError(path_, line_, "more than 2^31 - 1 lines");
  ++line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

std::optional<double> parse_double(const std::string& token, std::string& why) {
  const char* s = token.c_str();
  // strtod also takes "nan", "inf" and "infinity"; the format does not.
  for (const char ch : token)
    if (ch == 'n' || ch == 'N' || ch == 'i' || ch == 'I') {
      why = quote(token) + " is not a finite number";
      return std::nullopt;
    }
  char* end = nullptr;
  errno = 0;
  // glibc: correctly rounded, decimal and hex-float. In the C locale always: strtod follows
  // LC_NUMERIC, which a Python program that called setlocale may have made a decimal comma.
  static const locale_t c_locale = ::newlocale(LC_ALL_MASK, "C", locale_t(0));
  const double v = ::strtod_l(s, &end, c_locale);
  // The whole token: a NUL byte inside it would otherwise end it early.
  if (end == s || end != s + token.size()) {
    why = quote(token) + " is not a number";
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    why = quote(token) + " is outside the range of a double";
    return std::nullopt;
  }
  return v;
}

std::optional<double> parse_min_distance(const std::string& token, std::string& why) {
  const std::optional<double> d = parse_double(token, why);
  if (!d) return std::nullopt;
  if (*d < 0) {
    why = quote(token) + " is negative: a minimum distance is >= 0";
    return std::nullopt;
  }
  return *d + 0.0;  // -0 is 0
}

namespace {

// A `min-distance D` line: D for the queries after it (docs/formats.md).
double read_min_distance_line(const std::vector<std::string>& tok, const std::string& path,
                              long lineno) {
  if (tok.size() != 2)
    throw InputError(path, lineno,
                     "expected 'min-distance D', found " + std::to_string(tok.size() - 1) +
                         " fields after 'min-distance'");
  std::string why;
  const std::optional<double> d = parse_min_distance(tok[1], why);
  if (!d) throw InputError(path, lineno, "min-distance: " + why);
  return *d;
}

}  // namespace

std::vector<QueryRecord> read_native(const std::string& path) {
  InputFile in(path);
  const long long max_queries = bound_value(kMaxQueries);
  std::vector<QueryRecord> out;
  std::string line;
  double min_distance = 0;  // until a `min-distance` line says otherwise
  try {
    while (in.next(line)) {
      const long lineno = in.line();
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      const std::vector<std::string> tok = split(line, ' ');
      if (tok.empty()) continue;
      if (tok[0] == "min-distance") {
        min_distance = read_min_distance_line(tok, path, lineno);
        continue;
      }
      QueryRecord r;
      Query& q = r.query;
      q.min_distance = min_distance;
      if (tok[0] == "vf") {
        q.kind = QueryKind::VertexFace;
      } else if (tok[0] == "ee") {
        q.kind = QueryKind::EdgeEdge;
      } else {
        throw InputError(path, lineno,
                         "a query line starts with 'vf' or 'ee', not " + quote(tok[0]));
      }
      if (tok.size() != 26 && tok.size() != 27)
        throw InputError(
            path, lineno,
            "expected '" + tok[0] + " <id> <24 numbers> [truth]', found " +
                std::to_string(tok.size() < 2 ? 0 : tok.size() - 2) + " fields after the id" +
                (hash == std::string::npos ? std::string()
                                           : " (the '#' at column " + std::to_string(hash + 1) +
                                                 " starts a comment: an id cannot hold '#')"));
      if (has_control_byte(tok[1]))
        throw InputError(path, lineno, "the id " + quote(tok[1]) + " holds a control byte");
      check_query_count(out.size(), max_queries, in);
      r.id = tok[1];
      for (int i = 0; i < 24; ++i) {
        std::string why;
        const auto v = parse_double(tok[2 + i], why);
        if (!v) throw InputError(path, lineno, "number " + std::to_string(i + 1) + ": " + why);
        double* xyz[3] = {&q.x[i / 3].x, &q.x[i / 3].y, &q.x[i / 3].z};
        *xyz[i % 3] = *v;
      }
      if (tok.size() == 27) r.truth = parse_truth(tok[26], path, lineno);
      r.file = path;
      r.line = static_cast<int>(lineno);
      out.push_back(std::move(r));
    }
  } catch (const std::bad_alloc&) {
    out_of_memory(in, out.size());
  }
  return out;
}

std::vector<QueryRecord> read_benchmark_csv(const std::string& path, QueryKind kind) {
  InputFile in(path);
  const long long max_queries = bound_value(kMaxQueries);
  std::vector<QueryRecord> out;
  std::string line;
  QueryRecord r;
  int row = 0;
  try {
    while (in.next(line)) {
      const long lineno = in.line();
      if (line.find_first_not_of(" \t") == std::string::npos) continue;
      const std::vector<std::string> col = split(line, ',');
      if (col.size() != 7)
        throw InputError(
            path, lineno,
            "expected 7 comma-separated integers, found " + std::to_string(col.size()));
      if (row == 0) {
        check_query_count(out.size(), max_queries, in);
        r = QueryRecord{};
        r.query.kind = kind;
        r.file = path;
        r.line = static_cast<int>(lineno);
        r.id = std::to_string(out.size());
      }
      double xyz[3];
      for (int c = 0; c < 3; ++c) {
        mpz_class num, den;
        for (int k = 0; k < 2; ++k)
          if (!parse_integer(col[2 * c + k], k == 0 ? num : den))
            throw InputError(path, lineno,
                             "column " + std::to_string(2 * c + k + 1) + ": " +
                                 quote(col[2 * c + k]) + " is not an integer");
        if (den == 0) throw InputError(path, lineno, "zero denominator");
        mpq_class v(num, den);
        v.canonicalize();
        const double d = v.get_d();  // truncates; exact iff the value is a double
        if (!std::isfinite(d) || mpq_class(d) != v)
          throw InputError(path, lineno,
                           quote(trimmed(col[2 * c]) + "/" + trimmed(col[2 * c + 1])) +
                               " is not exactly a double");
        xyz[c] = d;
      }
      r.query.x[row] = Vec3{xyz[0], xyz[1], xyz[2]};
      const Truth truth = parse_truth(trimmed(col[6]), path, lineno);
      if (row > 0 && truth != r.truth)
        throw InputError(path, lineno, "the truth column differs within one query");
      r.truth = truth;
      if (++row == 8) {
        out.push_back(r);
        row = 0;
      }
    }
  } catch (const std::bad_alloc&) {
    out_of_memory(in, out.size());
  }
  if (row != 0)
    throw InputError(path, in.line(),
                     "the file ends inside a query (" + std::to_string(row) + " of 8 rows)");
  return out;
}

std::optional<QueryKind> kind_from_folder(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(path), ec);
  if (ec) p = fs::path(path);
  const std::string folder = p.lexically_normal().parent_path().filename().string();
  if (folder == "vertex-face") return QueryKind::VertexFace;
  if (folder == "edge-edge") return QueryKind::EdgeEdge;
  return std::nullopt;
}

std::vector<QueryRecord> read_query_file(const std::string& path, std::optional<QueryKind> kind) {
  const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  if (!csv) return read_native(path);
  const std::optional<QueryKind> folder = kind_from_folder(path);
  const auto name = [](QueryKind k) { return k == QueryKind::EdgeEdge ? "ee" : "vf"; };
  if (folder && kind && *folder != *kind)
    throw InputError(path, 0,
                     std::string("its folder makes it ") + name(*folder) + ", but --kind " +
                         name(*kind) + " was given; drop --kind or move the file");
  if (folder) kind = folder;
  if (!kind)
    throw InputError(path, 0,
                     "cannot tell vertex-face from edge-edge: its folder is not named "
                     "vertex-face or edge-edge; pass --kind vf or --kind ee");
  return read_benchmark_csv(path, *kind);
}

void write_native(std::ostream& os, const QueryRecord& r, double& min_distance) {
  if (r.query.min_distance != min_distance) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "min-distance %a\n", r.query.min_distance);
    os << buf;
    min_distance = r.query.min_distance;
  }
  os << (r.query.kind == QueryKind::VertexFace ? "vf " : "ee ") << r.id;
  char buf[64];
  for (const Vec3& p : r.query.x)
    for (int c = 0; c < 3; ++c) {
      std::snprintf(buf, sizeof buf, " %a", p[c]);
      os << buf;
    }
  if (r.has_truth()) os << ' ' << (r.truth == Truth::Yes ? 1 : 0);
  os << '\n';
}

}  // namespace fdh::verify

namespace fdh::verify {

void write_native(std::ostream& os, const QueryRecord& r) {
  double min_distance = 0;  // a stream of its own starts at 0
  write_native(os, r, min_distance);
}

}  // namespace fdh::verify

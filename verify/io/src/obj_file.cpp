#include "fdh/io/obj_file.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "fdh/io/input_error.hpp"
#include "fdh/io/line_words.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

// What follows the keyword, trimmed: an object's name may hold blanks.
std::string rest_of(std::string_view line, std::string_view keyword) {
  std::string_view s = line.substr(line.find(keyword) + keyword.size());
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

// The statements of the OBJ specification (Wavefront, "Object Files (.obj)", Appendix B1 of the
// Advanced Visualizer manual) that carry no triangle: read past. Any other first word is refused,
// so that a line the reader cannot read (a byte-order mark glued to `o cloth`) never silently
// moves faces between the cloth and the obstacles.
bool ignored_statement(std::string_view w) {
  static const std::set<std::string_view> kIgnored = {
      "vt",        "vn",       "vp",       "cstype", "deg",    "bmat",   "step",
      "p",         "l",        "curv",     "curv2",  "surf",   "parm",   "trim",
      "hole",      "scrv",     "sp",       "end",    "con",    "s",      "mg",
      "bevel",     "c_interp", "d_interp", "lod",    "usemtl", "mtllib", "shadow_obj",
      "trace_obj", "ctech",    "stech",    "maplib", "usemap", "call",   "csh"};
  return kIgnored.count(w) > 0;
}

// A file's first line: a UTF-8 byte-order mark is dropped; UTF-16 and UTF-32 (by their marks, or
// by the NUL bytes that every ASCII character carries in them) are refused by name.
std::string_view without_byte_order_mark(std::string_view line, const std::string& path) {
  if (line.substr(0, 3) == "\xEF\xBB\xBF") return line.substr(3);
  const bool utf32 = line.substr(0, 4) == std::string_view("\x00\x00\xFE\xFF", 4) ||
                     line.substr(0, 4) == std::string_view("\xFF\xFE\x00\x00", 4);
  const bool utf16 = line.substr(0, 2) == "\xFF\xFE" || line.substr(0, 2) == "\xFE\xFF";
  if (utf16 || utf32 || line.find('\0') != std::string_view::npos)
    throw InputError(path, 1,
                     std::string("the file is ") +
                         (utf32   ? "UTF-32"
                          : utf16 ? "UTF-16"
                                  : "not text (it holds NUL bytes: UTF-16?)") +
                         "; an OBJ file must be UTF-8 or ASCII (save it as UTF-8)");
  return line;
}

// Builds an ObjFile line by line.
class ObjReader {
 public:
  explicit ObjReader(const std::string& path) : in_(path) { obj_.path = path; }

  ObjFile read() {
    std::string line;
    while (in_.next(line)) take(line);
    check_forward_indices();
    std::vector<ObjObject> kept;
    for (ObjObject& o : obj_.objects)
      if (!o.tris.empty()) kept.push_back(std::move(o));
    obj_.objects = std::move(kept);
    return std::move(obj_);
  }

 private:
  void take(std::string_view line) {
    if (in_.line() == 1) line = without_byte_order_mark(line, in_.path());
    const std::vector<std::string_view> w = line_words(line);
    if (w.empty() || w[0][0] == '#') return;
    if (w[0] == "v") return vertex(w);
    if (w[0] == "f") return face(w);
    if (w[0] == "o" || w[0] == "g") return start_object(rest_of(line, w[0]));
    if (!ignored_statement(w[0]))
      fail("unknown statement " + quote(w[0]) +
           ": not an OBJ keyword (v, f, o, g, and the ones read past: docs/audit.md)");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(in_.path(), in_.line(), what);
  }

  void vertex(const std::vector<std::string_view>& w) {
    if (w.size() < 4) fail("a vertex needs three coordinates, not " + std::to_string(w.size() - 1));
    double c[3];
    for (int i = 0; i < 3; ++i)
      if (!parse_finite(w[std::size_t(i) + 1], c[i]))
        fail("coordinate " + std::to_string(i + 1) + ": " + number_refusal(w[std::size_t(i) + 1]));
    if (obj_.x.size() >= std::size_t(std::numeric_limits<int>::max() - 1))
      fail("more than 2^31 - 2 vertices");
    obj_.x.push_back({c[0], c[1], c[2]});
    obj_.vertex_lines.push_back(int(in_.line()));
  }

  // A corner's vertex index, 0-based; a positive one is checked against the file's vertex count
  // at its end (check_forward_indices).
  int corner(std::string_view token, int n) const {
    const std::string_view v = token.substr(0, token.find('/'));
    long long i = 0;
    const char* end = v.data() + v.size();
    const auto [p, ec] = std::from_chars(v.data(), end, i);
    if (v.empty() || ec != std::errc() || p != end)
      fail("corner " + std::to_string(n) + ": " + quote(token) + " is not a vertex index");
    if (i == 0) fail("corner " + std::to_string(n) + ": vertex index 0 (OBJ counts from 1)");
    const long long have = (long long)obj_.x.size();
    if (i < 0 && i < -have)
      fail("corner " + std::to_string(n) + ": vertex index " + std::to_string(i) + " with only " +
           std::to_string(have) + " vertices before it");
    if (i > std::numeric_limits<int>::max())
      fail("corner " + std::to_string(n) + ": vertex index " + std::to_string(i) +
           " is out of range");
    return i < 0 ? int(have + i) : int(i - 1);
  }

  void face(const std::vector<std::string_view>& w) {
    if (w.size() < 4) fail("a face needs at least 3 vertices, not " + std::to_string(w.size() - 1));
    std::vector<int> c;
    for (std::size_t k = 1; k < w.size(); ++k) {
      c.push_back(corner(w[k], int(k)));
      for (std::size_t j = 0; j + 1 < c.size(); ++j)
        if (c[j] == c.back())
          fail("a degenerate face: vertex " + std::to_string(c.back() + 1) + " twice");
    }
    if (c.size() > 3) ++obj_.polygons;
    ObjObject& o = current();
    for (std::size_t k = 1; k + 1 < c.size(); ++k) {
      o.tris.push_back({c[0], c[k], c[k + 1]});
      o.lines.push_back(int(in_.line()));
    }
  }

  void start_object(std::string name) {
    const auto [it, fresh] = index_.emplace(name, obj_.objects.size());
    if (fresh) obj_.objects.push_back({std::move(name), {}, {}});
    current_ = it->second;
  }

  ObjObject& current() {
    if (current_ == npos) start_object("");
    return obj_.objects[current_];
  }

  // A positive index may name a vertex defined later in the file; past the last one it is an
  // error at its face's line.
  void check_forward_indices() const {
    const int n = int(obj_.x.size());
    for (const ObjObject& o : obj_.objects)
      for (std::size_t t = 0; t < o.tris.size(); ++t)
        for (const int i : o.tris[t])
          if (i >= n)
            throw InputError(obj_.path, o.lines[t],
                             "vertex index " + std::to_string(i + 1) + " with only " +
                                 std::to_string(n) + " vertices in the file");
  }

  static constexpr std::size_t npos = std::size_t(-1);
  InputFile in_;
  ObjFile obj_;
  std::map<std::string, std::size_t> index_;
  std::size_t current_ = npos;
};

}  // namespace

const ObjObject* ObjFile::object(const std::string& name) const {
  for (const ObjObject& o : objects)
    if (o.name == name) return &o;
  return nullptr;
}

bool parse_finite(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto [p, ec] = std::from_chars(token.data(), end, out, std::chars_format::general);
  if (ec == std::errc() && p == end) return std::isfinite(out);
  // The rarer numbers the query files take too (parse_double): hex floats, and a decimal below
  // the smallest double, rounded to it or to 0 as strtod rounds.
  std::string why;
  const std::optional<double> v = parse_double(std::string(token), why);
  if (v) out = *v;
  return v.has_value();
}

std::string number_refusal(std::string_view token) {
  std::string why;
  if (!parse_double(std::string(token), why)) return why;
  return quote(token) + " is not a number";
}

ObjFile read_obj(const std::string& path) {
  return ObjReader(path).read();
}

}  // namespace fdh::verify

// A small PLY reader of our own: Debian packages no PLY library that fits (assimp reads
// coordinates as float and merges vertices; CGAL's reader is reference/'s and names no byte
// offset), and the format is short: a text header, then the elements (the PLY format as Greg
// Turk described it, 1994; docs/audit.md).
#include "fdh/io/ply_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "fdh/io/input_error.hpp"
#include "fdh/io/line_words.hpp"
#include "ply_header.hpp"

namespace fdh::verify {
namespace {

using ply::Element;
using ply::Format;
using ply::Header;
using ply::is_float;
using ply::Property;
using ply::size_of;
using ply::Type;

std::string read_whole(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  const long long max = bound_value(kMaxFileBytes);
  std::string bytes;
  std::vector<char> buffer(1 << 16);
  while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0) {
    bytes.append(buffer.data(), std::size_t(in.gcount()));
    if ((long long)bytes.size() > max)
      throw InputError(
          path, 0,
          "the file passes " + std::to_string(max) + " bytes; " + bound_text(kMaxFileBytes, max));
  }
  return bytes;
}

// A decoded binary value: integers assembled by shifts, so any host reads either byte order.
double decode(const unsigned char* p, Type t, bool big) {
  const int n = size_of(t);
  std::uint64_t u = 0;
  for (int i = 0; i < n; ++i) u |= std::uint64_t(p[big ? i : n - 1 - i]) << (8 * (n - 1 - i));
  switch (t) {
    case Type::I8:
      return double(std::int8_t(std::uint8_t(u)));
    case Type::U8:
      return double(u);
    case Type::I16:
      return double(std::int16_t(std::uint16_t(u)));
    case Type::U16:
      return double(u);
    case Type::I32:
      return double(std::int32_t(std::uint32_t(u)));
    case Type::U32:
      return double(u);
    case Type::F32: {
      const auto v = std::uint32_t(u);
      float f;
      std::memcpy(&f, &v, 4);
      return double(f);
    }
    case Type::F64:
      break;
  }
  double d;
  std::memcpy(&d, &u, 8);
  return d;
}

// The body's values in order, ascii (one element a line) or binary, and where each item starts.
class Body {
 public:
  Body(const std::string& path, const std::string& bytes, const Header& h)
      : path_(path), bytes_(bytes), format_(h.format), at_(h.body), line_(h.lines) {}

  bool ascii() const { return format_ == Format::Ascii; }
  // The line (ascii) or byte offset (binary) where the item begun by start() starts.
  long long where() const { return where_; }

  // Starts item j of `element` (named in messages as "vertex 12").
  void start(const std::string& element, long long j) {
    element_ = &element, item_ = j;
    if (!ascii()) return void(where_ = (long long)at_);
    std::string_view line;
    do {
      if (at_ >= bytes_.size()) fail_at(line_, "the file ends before " + item());
      std::size_t end = bytes_.find('\n', at_);
      if (end == std::string::npos) end = bytes_.size();
      line = std::string_view(bytes_).substr(at_, end - at_);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      at_ = end + 1, ++line_;
    } while (line_words(line).empty());
    words_ = line_words(line), next_word_ = 0, where_ = line_;
  }

  void end() const {
    if (ascii() && next_word_ < words_.size())
      fail_at(where_, item() + " has " + std::to_string(words_.size()) +
                          " values, more than its properties take");
  }

  // The next value of the item's property `name` (its list's count with `count`).
  double value(Type t, const std::string& name, bool count = false) {
    const auto what = [&] { return item() + "'s " + name + (count ? " count" : ""); };
    double v = 0;
    if (ascii()) {
      if (next_word_ >= words_.size()) fail_at(where_, what() + ": a value is missing");
      const std::string_view w = words_[next_word_++];
      if (!parse_finite(w, v))
        fail_at(where_, what() + ": " + quote(w) + " is not a finite number");
    } else {
      const auto n = std::size_t(size_of(t));
      if (bytes_.size() - std::min(at_, bytes_.size()) < n)
        fail_at((long long)at_, "the file ends inside " + what() + " (it has " +
                                    std::to_string(bytes_.size()) + " bytes)");
      v = decode(reinterpret_cast<const unsigned char*>(bytes_.data() + at_), t,
                 format_ == Format::Big);
      if (!std::isfinite(v)) fail_at((long long)at_, what() + " is not a finite number");
      at_ += n;
    }
    if (!is_float(t) && v != std::floor(v)) fail_at(where_, what() + " must be a whole number");
    return v;
  }

  // Nothing may follow the last element.
  void finish() const {
    if (ascii()) {
      for (std::size_t i = at_; i < bytes_.size(); ++i)
        if (!std::isspace((unsigned char)bytes_[i]))
          fail_at(line_ + 1, "text after the last element");
    } else if (at_ < bytes_.size()) {
      fail_at((long long)at_, std::to_string(bytes_.size() - at_) +
                                  " bytes after the last element; the header accounts for " +
                                  std::to_string(at_));
    }
  }

  [[noreturn]] void fail_at(long long where, const std::string& what) const {
    if (ascii()) throw InputError(path_, long(where), what);
    throw InputError(path_, 0, "byte " + std::to_string(where) + ": " + what);
  }

 private:
  std::string item() const { return *element_ + " " + std::to_string(item_); }

  const std::string& path_;
  const std::string& bytes_;
  const std::string* element_ = nullptr;
  long long item_ = 0;
  Format format_;
  std::size_t at_;
  long line_;
  long long where_ = 0;
  std::vector<std::string_view> words_;
  std::size_t next_word_ = 0;
};

int place(long long where) {
  return where > std::numeric_limits<int>::max() ? -1 : int(where);
}

bool is_index_list(const Property& p) {
  return p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// The elements read in order: the vertices' x, y, z and the faces' index lists kept, the rest
// skipped; then the faces checked and split into triangles.
class PlyReader {
 public:
  PlyReader(const std::string& path, const std::string& bytes, const Header& h)
      : path_(path), header_(h), body_(path, bytes, h) {
    obj_.path = path;
    obj_.byte_offsets = !body_.ascii();
  }

  ObjFile read() {
    check_header();
    for (const Element& e : header_.elements) read_element(e);
    body_.finish();
    triangles();
    return std::move(obj_);
  }

 private:
  const Element* element(const std::string& name) const {
    for (const Element& e : header_.elements)
      if (e.name == name) return &e;
    return nullptr;
  }

  void check_header() const {
    const Element* v = element("vertex");
    if (!v) throw InputError(path_, header_.lines, "the header has no vertex element");
    if (v->count >= std::numeric_limits<int>::max() - 1)
      throw InputError(path_, v->line, "more than 2^31 - 2 vertices");
    for (const char* axis : {"x", "y", "z"}) {
      const Property* p = nullptr;
      for (const Property& q : v->props)
        if (q.name == axis) p = &q;
      if (!p || p->list || !is_float(p->type))
        throw InputError(path_, v->line,
                         std::string("the vertex element needs a property ") + axis +
                             " of type float or double");
    }
    const Element* f = element("face");
    if (!f) return;
    for (const Property& q : f->props)
      if (is_index_list(q)) return;
    throw InputError(path_, f->line, "the face element has no list property vertex_indices");
  }

  void read_element(const Element& e) {
    const bool vertex = &e == element("vertex"), face = &e == element("face");
    for (long long j = 0; j < e.count; ++j) {
      body_.start(e.name, j);
      Vec3 p{0, 0, 0};
      std::vector<long long> corners;
      for (const Property& q : e.props) {
        if (!q.list) {
          const double v = body_.value(q.type, q.name);
          double* axis = q.name == "x"   ? &p.x
                         : q.name == "y" ? &p.y
                         : q.name == "z" ? &p.z
                                         : nullptr;
          if (vertex && axis) *axis = v;
          continue;
        }
        const auto n = (long long)body_.value(q.count, q.name, true);
        const bool kept = face && is_index_list(q);
        for (long long k = 0; k < n; ++k) {
          const double i = body_.value(q.type, q.name);
          if (kept) corners.push_back((long long)i);
        }
      }
      body_.end();
      if (vertex) obj_.x.push_back(p), obj_.vertex_lines.push_back(place(body_.where()));
      if (face) faces_.push_back({std::move(corners), body_.where()});
    }
  }

  void triangles() {
    ObjObject o;
    const auto n = (long long)obj_.x.size();
    for (const auto& [c, where] : faces_) {
      if (c.size() < 3)
        body_.fail_at(where, "a face needs at least 3 vertices, not " + std::to_string(c.size()));
      for (std::size_t k = 0; k < c.size(); ++k) {
        if (c[k] < 0 || c[k] >= n)
          body_.fail_at(where, "corner " + std::to_string(k + 1) + ": vertex index " +
                                   std::to_string(c[k]) + " with " + std::to_string(n) +
                                   " vertices (PLY counts from 0)");
        for (std::size_t m = 0; m < k; ++m)
          if (c[m] == c[k])
            body_.fail_at(where, "a degenerate face: vertex " + std::to_string(c[k]) + " twice");
      }
      if (c.size() > 3) ++obj_.polygons;
      for (std::size_t k = 1; k + 1 < c.size(); ++k) {
        o.tris.push_back({int(c[0]), int(c[k]), int(c[k + 1])});
        o.lines.push_back(place(where));
      }
    }
    if (!o.tris.empty()) obj_.objects.push_back(std::move(o));
  }

  const std::string& path_;
  const Header& header_;
  Body body_;
  ObjFile obj_;
  std::vector<std::pair<std::vector<long long>, long long>> faces_;  // corners, where
};

}  // namespace

ObjFile read_ply(const std::string& path) {
  const std::string bytes = read_whole(path);
  const Header header = ply::read_header(path, bytes);
  return PlyReader(path, bytes, header).read();
}

}  // namespace fdh::verify

#include "ply_header.hpp"

#include "fdh/io/input_error.hpp"
#include "fdh/io/line_words.hpp"

namespace fdh::verify::ply {
namespace {

bool type_named(std::string_view w, Type& t) {
  static const std::pair<const char*, Type> names[] = {
      {"char", Type::I8},   {"int8", Type::I8},     {"uchar", Type::U8},   {"uint8", Type::U8},
      {"short", Type::I16}, {"int16", Type::I16},   {"ushort", Type::U16}, {"uint16", Type::U16},
      {"int", Type::I32},   {"int32", Type::I32},   {"uint", Type::U32},   {"uint32", Type::U32},
      {"float", Type::F32}, {"float32", Type::F32}, {"double", Type::F64}, {"float64", Type::F64}};
  for (const auto& [name, type] : names)
    if (w == name) return t = type, true;
  return false;
}

// The text header, line by line, up to and with `end_header`.
class HeaderReader {
 public:
  HeaderReader(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  Header read() {
    std::string_view line;
    if (!next(line) || line != "ply") fail("not a PLY file: the first line must be 'ply'");
    bool format = false;
    for (;;) {
      if (!next(line)) fail("the header ends without an end_header line");
      const std::vector<std::string_view> w = line_words(line);
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "end_header") break;
      if (w[0] == "format")
        read_format(w), format = true;
      else if (w[0] == "element")
        element(w);
      else if (w[0] == "property")
        property(w);
      else
        fail("unknown header line " + quote(line));
    }
    if (!format) fail("no format line before end_header");
    header_.body = at_, header_.lines = line_;
    return header_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

  bool next(std::string_view& line) {
    if (at_ >= bytes_.size()) return false;
    std::size_t end = bytes_.find('\n', at_);
    if (end == std::string::npos) end = bytes_.size();
    line = std::string_view(bytes_).substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at_ = end + 1, ++line_;
    return true;
  }

  void read_format(const std::vector<std::string_view>& w) {
    if (w.size() != 3 || w[2] != "1.0")
      fail("the format line must be 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    if (w[1] == "ascii")
      header_.format = Format::Ascii;
    else if (w[1] == "binary_little_endian")
      header_.format = Format::Little;
    else if (w[1] == "binary_big_endian")
      header_.format = Format::Big;
    else
      fail("unknown format " + quote(w[1]) + " (ascii, binary_little_endian or binary_big_endian)");
  }

  void element(const std::vector<std::string_view>& w) {
    long long n = -1;
    if (w.size() == 3) parse_count(w[2], n);
    if (n < 0) fail("an element line must be 'element NAME COUNT', COUNT a whole number");
    header_.elements.push_back({std::string(w[1]), n, {}, line_});
  }

  static void parse_count(std::string_view s, long long& n) {
    n = 0;
    for (const char c : s) {
      if (c < '0' || c > '9' || n > (1LL << 40)) return void(n = -1);
      n = n * 10 + (c - '0');
    }
    if (s.empty()) n = -1;
  }

  void property(const std::vector<std::string_view>& w) {
    if (header_.elements.empty()) fail("a property before any element");
    Property p;
    const bool list = w.size() == 5 && w[1] == "list";
    if (!(list || w.size() == 3))
      fail("a property line must be 'property TYPE NAME' or 'property list COUNT TYPE NAME'");
    p.list = list;
    if (list && !type_named(w[2], p.count)) fail("unknown type " + quote(w[2]));
    if (list && is_float(p.count)) fail("a list's count must be of an integer type");
    if (!type_named(w[list ? 3 : 1], p.type)) fail("unknown type " + quote(w[list ? 3 : 1]));
    p.name = std::string(w.back());
    header_.elements.back().props.push_back(p);
  }

  const std::string& path_;
  const std::string& bytes_;
  std::size_t at_ = 0;
  long line_ = 0;
  Header header_;
};

}  // namespace

Header read_header(const std::string& path, const std::string& bytes) {
  return HeaderReader(path, bytes).read();
}

}  // namespace fdh::verify::ply

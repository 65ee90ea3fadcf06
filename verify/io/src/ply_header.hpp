// The PLY header (the PLY format as Greg Turk described it, 1994): its elements and properties,
// read line by line up to `end_header`. Private to verify/io (ply_file.cpp reads the body).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fdh::verify::ply {

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };
enum class Format { Ascii, Little, Big };

struct Property {
  std::string name;
  Type type = Type::F32;
  bool list = false;
  Type count = Type::U8;  // a list's count type
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> props;
  long line = 0;  // its header line
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t body = 0;  // the first byte after the end_header line
  long lines = 0;        // the header's lines
};

inline int size_of(Type t) {
  static const int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[int(t)];
}

inline bool is_float(Type t) {
  return t == Type::F32 || t == Type::F64;
}

// The header of the file `path` whose bytes are `bytes`; InputError naming the line.
Header read_header(const std::string& path, const std::string& bytes);

}  // namespace fdh::verify::ply

// The hash that names a stored case (a query's, a peers case's): the same case found twice (by
// two threads, two shards, or a resumed run) is one file. FNV-1a over 64 bits.
#pragma once

#include <cstdint>
#include <string>

namespace fdh::verify {

class CaseHash {
 public:
  // v's 8 bytes, lowest first.
  void add(std::uint64_t v);
  // v's bits, with -0 taken as +0: the same case.
  void add_coordinate(double v);
  // 16 hex digits.
  std::string hex() const;

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

}  // namespace fdh::verify

// One collision query in plain doubles, as read from a file or recorded by a simulation.
#pragma once

#include <array>
#include <string>

#include "fdh/vec3.hpp"

namespace fdh {

enum class QueryKind { VertexFace, EdgeEdge };

struct Query {
  QueryKind kind = QueryKind::VertexFace;
  std::string id;
  // vf: p0 a0 b0 c0 p1 a1 b1 c1 (point and triangle at t = 0, then at t = 1).
  // ee: ea0 ea1 eb0 eb1 at t = 0, then at t = 1.
  std::array<Vec3, 8> x{};
  int truth = -1;  // 0 or 1 when the file gives it, else -1
  std::string file;
  int line = 0;  // first line of the query in `file`

  bool has_truth() const { return truth >= 0; }
  // A vertex-face query whose triangle stands still: the paper's setting.
  bool is_static_vf() const {
    return kind == QueryKind::VertexFace && x[5] == x[1] && x[6] == x[2] && x[7] == x[3];
  }
  // The paper's names for a static vf query: B, B', D, E, F.
  const Vec3& b0() const { return x[0]; }
  const Vec3& b1() const { return x[4]; }
  const Vec3& d() const { return x[1]; }
  const Vec3& e() const { return x[2]; }
  const Vec3& f() const { return x[3]; }
};

}  // namespace fdh

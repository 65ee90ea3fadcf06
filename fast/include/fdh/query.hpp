// One collision query: the geometry, 8 points in plain doubles, and the minimum separation it
// asks about (0: contact). Where a query came from
// (a file's line, an id) and what a file says of it (its truth) is a record of verify/io
// (fdh/io/query_record.hpp), not part of the query.
#pragma once

#include <array>

#include "fdh/vec3.hpp"

namespace fdh {

enum class QueryKind { VertexFace, EdgeEdge };

struct Query {
  QueryKind kind = QueryKind::VertexFace;
  // The points at t = 0 (x[0..3]), then the same points at t = 1 (x[4..7]), named as in the
  // CCD benchmark (Wang et al. 2021):
  //   vertex-face: v, f0, f1, f2 (the vertex, then the triangle's corners);
  //   edge-edge:   ea0, ea1, eb0, eb1 (edge a's ends, then edge b's).
  std::array<Vec3, 8> x{};
  // The minimum separation δ (docs/methods.md, "Minimum separation"): the query asks whether the
  // closed primitives come within Euclidean distance δ, taken at the double's exact value, at
  // some time of the step (the earliest such time is t*_δ). δ = 0 asks for contact, today's
  // question, and every method answers it as it did before δ existed. Finite and >= 0.
  double min_distance = 0;

  // Vertex-face.
  const Vec3& v_t0() const { return x[0]; }
  const Vec3& f0_t0() const { return x[1]; }
  const Vec3& f1_t0() const { return x[2]; }
  const Vec3& f2_t0() const { return x[3]; }
  const Vec3& v_t1() const { return x[4]; }
  const Vec3& f0_t1() const { return x[5]; }
  const Vec3& f1_t1() const { return x[6]; }
  const Vec3& f2_t1() const { return x[7]; }

  // Edge-edge.
  const Vec3& ea0_t0() const { return x[0]; }
  const Vec3& ea1_t0() const { return x[1]; }
  const Vec3& eb0_t0() const { return x[2]; }
  const Vec3& eb1_t0() const { return x[3]; }
  const Vec3& ea0_t1() const { return x[4]; }
  const Vec3& ea1_t1() const { return x[5]; }
  const Vec3& eb0_t1() const { return x[6]; }
  const Vec3& eb1_t1() const { return x[7]; }

  // A vertex-face query whose triangle stands still: the paper's setting.
  bool is_static_vf() const {
    return kind == QueryKind::VertexFace && f0_t1() == f0_t0() && f1_t1() == f1_t0() &&
           f2_t1() == f2_t0();
  }
  // The paper's names for a static vertex-face query: the point moves from B to B' past the
  // still triangle DEF.
  const Vec3& b0() const { return v_t0(); }
  const Vec3& b1() const { return v_t1(); }
  const Vec3& d() const { return f0_t0(); }
  const Vec3& e() const { return f1_t0(); }
  const Vec3& f() const { return f2_t0(); }
};

}  // namespace fdh

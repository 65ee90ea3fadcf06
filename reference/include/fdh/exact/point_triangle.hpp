// `exact`: does the closed segment BB' meet the closed still triangle DEF? Exact rational
// arithmetic (CGAL + GMP) on exactly the given doubles. Zero motion, motion in the plane and
// zero-area triangles are valid inputs. Touching counts as a hit.
#pragma once

#include <string>

#include "fdh/vec3.hpp"

namespace fdh::exact {

enum class ContactKind {
  None,
  Face,     // the path crosses the plane through the triangle's interior
  Edge,     // ... through an edge's interior (or touches a zero-area triangle's segment)
  Vertex,   // ... through a vertex
  InPlane,  // the whole path lies in the triangle's plane and meets the triangle
};
const char* to_string(ContactKind k);

struct PointTriangleContact {
  bool hit = false;
  ContactKind kind = ContactKind::None;
  std::string time;  // earliest t in [0,1] with B + t(B'-B) on DEF: "p/q" or "p"; "" if no hit
};

PointTriangleContact point_triangle(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                    const Vec3& f);

// The same verdict by a second, independent exact method (CGAL's do_intersect), faster because
// it computes no time: the fallback of `robust`.
bool point_triangle_hit(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                        const Vec3& f);

}  // namespace fdh::exact

#include "fdh/exact/point_triangle.hpp"
#include "fdh/exact/triangle_triangle.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <array>
#include <sstream>
#include <variant>

namespace fdh::exact {
namespace {

// point_triangle(): a fast exit by CGAL's filtered exact predicate (Epick), then plain rational
// arithmetic (no filter at all) for the verdict, the contact kind and the contact time.
// point_triangle_hit(): CGAL's exact do_intersect. Neither shares float reasoning with fast/'s
// `robust`, and a property checks that the two agree.
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using FT = CGAL::Exact_rational;
using EK = CGAL::Simple_cartesian<FT>;
using Point = EK::Point_3;
using Vector = EK::Vector_3;

Point to_exact(const Vec3& p) {
  return Point(p.x, p.y, p.z);
}
Epick::Point_3 to_epick(const Vec3& p) {
  return Epick::Point_3(p.x, p.y, p.z);
}

struct Contact {
  bool hit = false;
  ContactKind kind = ContactKind::None;
  FT time = 0;
};
const Contact kNone{};

// Clips the time interval [lo, hi] to {t : g0 + t (g1 - g0) >= 0}. False if it becomes empty.
bool clip(FT& lo, FT& hi, const FT& g0, const FT& g1) {
  if (g0 < 0 && g1 < 0) return false;
  if (g0 < 0) {
    const FT root = g0 / (g0 - g1);
    if (root > lo) lo = root;
  } else if (g1 < 0) {
    const FT root = g0 / (g0 - g1);
    if (root < hi) hi = root;
  }
  return lo <= hi;
}

// The path X(t) = P + t d against a zero-area triangle: the segment [A, B] between its two
// farthest vertices, or the single point A when A = B.
Contact path_segment(const Point& P, const Vector& d, const Point& A, const Point& B) {
  const Vector e = B - A, r = A - P;
  if (e == CGAL::NULL_VECTOR) {  // a point
    if (d == CGAL::NULL_VECTOR) return P == A ? Contact{true, ContactKind::Vertex, 0} : kNone;
    if (CGAL::cross_product(r, d) != CGAL::NULL_VECTOR) return kNone;
    const FT t = (r * d) / (d * d);
    return (t >= 0 && t <= 1) ? Contact{true, ContactKind::Vertex, t} : kNone;
  }
  const auto kind_at = [](const FT& s) {
    return (s == 0 || s == 1) ? ContactKind::Vertex : ContactKind::Edge;
  };
  const Vector w = CGAL::cross_product(d, e);
  if (w != CGAL::NULL_VECTOR) {    // lines not parallel: P + t d = A + s e
    if (r * w != 0) return kNone;  // skew
    const FT ww = w * w;
    const FT t = (CGAL::cross_product(r, e) * w) / ww;
    const FT s = (CGAL::cross_product(r, d) * w) / ww;
    if (t < 0 || t > 1 || s < 0 || s > 1) return kNone;
    return {true, kind_at(s), t};
  }
  // Parallel (or no motion): the path must lie on the segment's line; then clip
  // s(t) = ((P - A) + t d)·e / e·e to [0, 1].
  if (CGAL::cross_product(r, e) != CGAL::NULL_VECTOR) return kNone;
  const FT ee = e * e;
  const FT s0 = -(r * e) / ee, s1 = s0 + (d * e) / ee;
  FT lo = 0, hi = 1;
  if (!clip(lo, hi, s0, s1) || !clip(lo, hi, 1 - s0, 1 - s1)) return kNone;
  return {true, kind_at(s0 + lo * (s1 - s0)), lo};
}

Contact solve(const Vec3& b0, const Vec3& b1, const Vec3& d0, const Vec3& e0, const Vec3& f0) {
  // Fast exit, exact: both ends strictly on one side of a proper triangle's plane.
  // (All orientations are COPLANAR for a zero-area triangle, so it never exits here.)
  const Epick::Point_3 ed = to_epick(d0), ee = to_epick(e0), ef = to_epick(f0);
  const CGAL::Orientation o = CGAL::orientation(ed, ee, ef, to_epick(b0));
  if (o != CGAL::COPLANAR && o == CGAL::orientation(ed, ee, ef, to_epick(b1))) return kNone;

  const Point P = to_exact(b0), Q = to_exact(b1);
  const std::array<Point, 3> V = {to_exact(d0), to_exact(e0), to_exact(f0)};
  const Vector d = Q - P;
  const Vector n = CGAL::cross_product(V[1] - V[0], V[2] - V[0]);

  if (n == CGAL::NULL_VECTOR) {  // zero-area triangle: its hull is its longest side
    int best = 0;
    FT best_len = -1;
    for (int i = 0; i < 3; ++i) {
      const FT len = (V[(i + 1) % 3] - V[i]).squared_length();
      if (len > best_len) best = i, best_len = len;
    }
    return path_segment(P, d, V[best], V[(best + 1) % 3]);
  }

  // g_i(X) = ((V[i+1] - V[i]) × (X - V[i]))·n is >= 0 for all i iff X (in the plane) lies in
  // the closed triangle; g_i is linear in X, hence in t along the path.
  const auto g = [&](int i, const Point& X) {
    return CGAL::cross_product(V[(i + 1) % 3] - V[i], X - V[i]) * n;
  };
  const FT o0 = (P - V[0]) * n, o1 = (Q - V[0]) * n;  // signed heights (times |n|)

  if (o0 == 0 && o1 == 0) {  // the path lies in the plane: clip it by the three edges
    FT lo = 0, hi = 1;
    for (int i = 0; i < 3; ++i)
      if (!clip(lo, hi, g(i, P), g(i, Q))) return kNone;
    return {true, ContactKind::InPlane, lo};
  }
  if ((o0 > 0 && o1 > 0) || (o0 < 0 && o1 < 0)) return kNone;
  const FT t = o0 / (o0 - o1);  // the single crossing of the plane
  const Point X = P + t * d;
  int zeros = 0;
  for (int i = 0; i < 3; ++i) {
    const FT gi = g(i, X);
    if (gi < 0) return kNone;
    zeros += gi == 0;
  }
  const ContactKind kind =
      zeros == 0 ? ContactKind::Face : (zeros == 1 ? ContactKind::Edge : ContactKind::Vertex);
  return {true, kind, t};
}

std::string rational_string(const FT& q) {
  CGAL::Fraction_traits<FT>::Numerator_type num;
  CGAL::Fraction_traits<FT>::Denominator_type den;
  CGAL::Fraction_traits<FT>::Decompose()(q, num, den);
  std::ostringstream os;
  os << num;
  if (den != 1) os << '/' << den;
  return os.str();
}

}  // namespace

const char* to_string(ContactKind k) {
  switch (k) {
    case ContactKind::None:
      return "none";
    case ContactKind::Face:
      return "face";
    case ContactKind::Edge:
      return "edge";
    case ContactKind::Vertex:
      return "vertex";
    case ContactKind::InPlane:
      return "in-plane";
  }
  return "?";
}

PointTriangleContact point_triangle(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                    const Vec3& f) {
  const Contact c = solve(b0, b1, d, e, f);
  PointTriangleContact out;
  out.hit = c.hit;
  out.kind = c.kind;
  if (c.hit) out.time = rational_string(c.time);
  return out;
}

// The verdict alone, by CGAL's own exact (filtered) intersection test: a second exact
// implementation, independent of solve() above, and fast because CGAL's filters settle most
// signs in floating point. CGAL requires proper triangles and segments, so the zero-area and
// no-motion cases are reduced to segments and points first.
bool point_triangle_hit(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                        const Vec3& f) {
  using P3 = Epick::Point_3;
  using S3 = Epick::Segment_3;
  const P3 P = to_epick(b0), Q = to_epick(b1), D = to_epick(d), E = to_epick(e), F = to_epick(f);
  if (!CGAL::collinear(D, E, F)) {
    const Epick::Triangle_3 t(D, E, F);
    return P == Q ? t.has_on(P) : CGAL::do_intersect(t, S3(P, Q));
  }
  // Zero area: the hull is the segment between the two corners that the third lies between.
  P3 a = D, b = E;
  if (CGAL::collinear_are_ordered_along_line(E, D, F))
    a = E, b = F;
  else if (CGAL::collinear_are_ordered_along_line(D, E, F))
    a = D, b = F;
  if (a == b) return P == Q ? P == a : S3(P, Q).has_on(a);
  const S3 hull(a, b);
  return P == Q ? hull.has_on(P) : CGAL::do_intersect(hull, S3(P, Q));
}

namespace {

// A closed triangle as the simplex it spans: a proper triangle, a segment (zero area: the two
// corners the third lies between) or a point. CGAL requires proper triangles and segments.
using Simplex = std::variant<Epick::Triangle_3, Epick::Segment_3, Epick::Point_3>;

Simplex simplex(const std::array<Vec3, 3>& t) {
  using P3 = Epick::Point_3;
  const P3 D = to_epick(t[0]), E = to_epick(t[1]), F = to_epick(t[2]);
  if (!CGAL::collinear(D, E, F)) return Epick::Triangle_3(D, E, F);
  P3 a = D, b = E;
  if (CGAL::collinear_are_ordered_along_line(E, D, F))
    a = E, b = F;
  else if (CGAL::collinear_are_ordered_along_line(D, E, F))
    a = D, b = F;
  if (a == b && a == F) return a;
  if (a == b) return Epick::Segment_3(a, F);  // D = E: the hull is DF
  return Epick::Segment_3(a, b);
}

// Point against anything by has_on (or equality); the rest by do_intersect.
bool meet(const Epick::Point_3& p, const Epick::Point_3& q) {
  return p == q;
}
template <class S>
bool meet(const S& s, const Epick::Point_3& p) {
  return s.has_on(p);
}
template <class S>
bool meet(const Epick::Point_3& p, const S& s) {
  return s.has_on(p);
}
template <class S, class T>
bool meet(const S& s, const T& t) {
  return CGAL::do_intersect(s, t);
}

}  // namespace

bool triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  return std::visit([](const auto& s, const auto& t) { return meet(s, t); }, simplex(a),
                    simplex(b));
}

}  // namespace fdh::exact

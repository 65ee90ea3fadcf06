// The moving families: vertex-face with a moving triangle, and edge-edge. One function per
// family; the table at the end is their half of the registry.
#include <cmath>
#include <cstdint>

#include "constructions.hpp"
#include "draw.hpp"

namespace fdh::verify {
namespace {

// Unlike pick (draw.hpp), these keep RapidCheck's plain order, shrinking toward lo: the same
// seeds still give the cases they always gave.
int in(int lo, int hi) {
  return *rc::gen::inRange(lo, hi + 1);
}
double dy(int lo, int hi, int bits) {
  return std::ldexp(double(in(lo, hi)), -bits);
}
Vec3 point(int r) {
  return Vec3{double(in(-r, r)), double(in(-r, r)), double(in(-r, r))};
}

Generated make(QueryKind kind, const std::array<Vec3, 8>& x, Truth truth, std::string time = "") {
  Generated g;
  g.query.kind = kind;
  g.query.x = x;
  g.truth = truth;
  g.time = truth == Truth::Yes ? std::move(time) : "";
  return g;
}

QueryKind any_kind() {
  return *rc::gen::arbitrary<bool>() ? QueryKind::VertexFace : QueryKind::EdgeEdge;
}

// A rigid change of frame that keeps coordinates dyadic: a signed permutation of the axes, a
// power-of-two scale and a small integer translation. Truths and times do not change.
void reframe(std::array<Vec3, 8>& x) {
  const int perm = in(0, 5), scale = in(-20, 20);
  const Vec3 sign{double(2 * in(0, 1) - 1), double(2 * in(0, 1) - 1), double(2 * in(0, 1) - 1)};
  const Vec3 shift = point(64);
  for (Vec3& v : x) {
    const double c[3] = {v.x, v.y, v.z};
    static const int p[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    Vec3 w{c[p[perm][0]] * sign.x, c[p[perm][1]] * sign.y, c[p[perm][2]] * sign.z};
    v = std::ldexp(1.0, scale) * (w + shift);
  }
}

Generated random_linear() {
  std::array<Vec3, 8> x;
  for (Vec3& v : x) v = point(8);
  return make(any_kind(), x, Truth::Unknown);
}

// Every coordinate a random multiple of 2^-52 in [-1, 1], each vertex moving by up to 1/2 per
// axis: 53-bit mantissas, so exact ties have probability 0.
Generated generic_moving() {
  const auto r = [] {
    return std::ldexp(double(*rc::gen::inRange<std::int64_t>(-(1LL << 52), (1LL << 52) + 1)), -52);
  };
  std::array<Vec3, 8> x;
  for (int i = 0; i < 4; ++i) {
    x[i] = {r(), r(), r()};
    x[i + 4] = x[i] + 0.5 * Vec3{r(), r(), r()};
  }
  return make(any_kind(), x, Truth::Unknown);
}

// Turn by the angle with cos 3/5, sin 4/5 about z, then round to multiples of 2^-6.
Generated rotating() {
  std::array<Vec3, 8> x;
  for (int i = 0; i < 4; ++i) {
    x[i] = point(16);
    const Vec3 r{(3 * x[i].x - 4 * x[i].y) / 5, (4 * x[i].x + 3 * x[i].y) / 5, x[i].z};
    x[i + 4] = {std::round(r.x * 64) / 64, std::round(r.y * 64) / 64, r.z};
  }
  if (*rc::gen::arbitrary<bool>()) x[4] = x[0] + Vec3{dy(-64, 64, 4), dy(-64, 64, 4), 0};
  return make(any_kind(), x, Truth::Unknown);
}

// Corners q + u, q + v, q - u - v (centroid q) move straight to their mirror images through q:
// the triangle is the point q at t = 1/2 and turns inside out. A point at q is inside from the
// start. A point q + delta n off the plane never touches: the cubic is -delta |n|^2 (1 - 2t)^2,
// zero only when the triangle is the point q.
Generated hourglass() {
  const Vec3 q = point(8), u = point(8), v = point(8), w = -(u + v);
  const Vec3 n = cross(v - u, w - u);
  const bool hit = n == Vec3{} || *rc::gen::arbitrary<bool>();
  const Vec3 p = hit ? q : q + dy(1, 16, 4) * n;
  return make(QueryKind::VertexFace, {p, q + u, q + v, q + w, p, q - u, q - v, q - w},
              truth_of(hit), "0");
}

// Hinge a = (-4,0,0), b = (4,0,0); c = (0,4,z) with z from -4 to 4; the point (px, y, w) with y
// from 4s to -4s and w = -s (s = +-1) is on the plane when 4 w = y z, i.e. at t = 1/4 and 3/4.
// It is inside at the first (late = false) or the second meeting iff |px| <= 2 (the triangle is
// 4 wide at half height); at the other it is outside. Root parity sees two roots and reports no
// collision.
Generated two_crossings() {
  const bool late = *rc::gen::arbitrary<bool>();
  const double px = dy(-48, 48, 4), s = late ? -1 : 1;
  std::array<Vec3, 8> x = {Vec3{px, 4 * s, -s},  {-4, 0, 0}, {4, 0, 0}, {0, 4, -4},
                           Vec3{px, -4 * s, -s}, {-4, 0, 0}, {4, 0, 0}, {0, 4, 4}};
  const bool hit = std::fabs(px) <= 2;
  reframe(x);
  return make(QueryKind::VertexFace, x, truth_of(hit), late ? "3/4" : "1/4");
}

Generated coplanar() {
  std::array<Vec3, 8> x;
  for (Vec3& v : x) v = Vec3{double(in(-8, 8)), double(in(-8, 8)), 0};
  reframe(x);
  return make(any_kind(), x, Truth::Unknown);
}

// A rigid translation of the triangle by d; the point at a + s e with s from s0 to s1, on the
// edge line throughout: a hit iff [s0, s1] meets [0, 1]. (If c is on that line too, the
// triangle's trace on it may be longer than the edge: truth unknown.)
Generated sliding_on_edge() {
  const Vec3 a = point(8), b = point(8), c = point(8), d = point(4), e = b - a;
  const double s0 = dy(-32, 48, 4), s1 = dy(-32, 48, 4);
  const bool flat = cross(e, c - a) == Vec3{};
  const Truth truth =
      flat ? Truth::Unknown : truth_of(std::fmax(s0, s1) >= 0 && std::fmin(s0, s1) <= 1);
  const bool at_start = s0 >= 0 && s0 <= 1;
  return make(QueryKind::VertexFace, {a + s0 * e, a, b, c, a + d + s1 * e, a + d, b + d, c + d},
              truth, at_start ? "0" : "");
}

// A on the x axis, B along x too, its line crossing A's line at t = 1/2 (y and z both pass 0
// then) unless z misses by dz: then the lines never meet.
Generated parallel_edges() {
  const double xa = dy(-32, 32, 2), la = dy(0, 32, 2), va = dy(-32, 32, 2);
  const double xb = dy(-32, 32, 2), lb = dy(0, 32, 2), vb = dy(-32, 32, 2);
  const double y = dy(1, 32, 2), z = dy(-32, 32, 2);
  const bool miss = *rc::gen::arbitrary<bool>();
  const double dz = miss ? dy(1, 16, 6) : 0;
  std::array<Vec3, 8> x = {Vec3{xa, 0, 0},
                           {xa + la, 0, 0},
                           {xb, y, z},
                           {xb + lb, y, z},
                           Vec3{xa + va, 0, 0},
                           {xa + la + va, 0, 0},
                           {xb + vb, -y, -z + dz},
                           {xb + lb + vb, -y, -z + dz}};
  // At t = 1/2: A = [xa + va/2, xa + la + va/2], B = [xb + vb/2, xb + lb + vb/2].
  const double a0 = xa + va / 2, a1 = a0 + la, b0 = xb + vb / 2, b1 = b0 + lb;
  const bool hit = !miss && a0 <= b1 && b0 <= a1;
  reframe(x);
  return make(QueryKind::EdgeEdge, x, truth_of(hit), "1/2");
}

Generated degenerate_edge() {
  const Vec3 m = point(8), e = point(8), b0 = point(8), b1 = point(8), d = point(4);
  std::array<Vec3, 8> x = {m + e, m - e, b0, b1, m + d - e, m + d + e, b0 + d, b1 + point(4)};
  return make(QueryKind::EdgeEdge, x, Truth::Unknown);
}

}  // namespace

std::vector<Family> moving_families() {
  return {
      {"random-linear", true, "vf or ee, every vertex anywhere in a small box at t = 0 and t = 1",
       random_linear},
      {"generic-moving", true,
       "vf or ee, full-precision random coordinates: no exact coincidence, the speed case of a "
       "simulator's typical query",
       generic_moving},
      {"rotating", true,
       "a triangle or edge turned about an axis, the turn replaced by straight lines", rotating},
      {"hourglass", true,
       "Brochu et al. 2012: the triangle shrinks through a point and turns inside out", hourglass},
      {"two-crossings", true,
       "the point meets the tilting plane twice; one meeting is inside, one is not", two_crossings},
      {"coplanar", true, "every vertex in one plane throughout", coplanar},
      {"sliding-on-edge", true,
       "the point slides along the line of a triangle edge, on it or past its end",
       sliding_on_edge},
      {"parallel-edges", true,
       "ee: parallel edges whose lines coincide at t = 1/2, or miss by a hair", parallel_edges},
      {"degenerate-edge", true, "ee: an edge that shrinks to a point at t = 1/2", degenerate_edge},
  };
}

}  // namespace fdh::verify

// The static vertex-face families: a point B moving to B' against a triangle DEF that stands
// still. One function per family; the table at the end is their half of the registry.
#include <cmath>
#include <iterator>
#include <numeric>
#include <string>

#include "constructions.hpp"
#include "draw.hpp"
#include "fdh/dyadic.hpp"

namespace fdh::verify {
namespace {

struct Triangle {
  Vec3 d, e, f, n;  // n = DE × DF, exact for small integer vertices
  Vec3 vertex(int i) const { return i == 0 ? d : (i == 1 ? e : f); }
  // D + a DE + b DF: exact for a, b with few bits.
  Vec3 at(double a, double b) const { return d + a * (e - d) + b * (f - d); }
};

// Zero-area draws (rare) become a unit right triangle at D: no retry loop, so shrinking stays
// simple.
Triangle gen_triangle() {
  Triangle t{small_point(16), small_point(16), small_point(16), {}};
  t.n = cross(t.e - t.d, t.f - t.d);
  if (t.n == Vec3{}) {
    t.e = t.d + Vec3{1, 0, 0};
    t.f = t.d + Vec3{0, 1, 0};
    t.n = cross(t.e - t.d, t.f - t.d);
  }
  return t;
}

// Barycentric (a, b) in [-1/2, 3/2] with 8 bits; inside the closed triangle iff a, b >= 0 and
// a + b <= 1, decided exactly.
struct InPlanePoint {
  Vec3 x;
  bool inside;
};
InPlanePoint gen_in_plane(const Triangle& t) {
  const double a = dyadic(-128, 384, 8), b = dyadic(-128, 384, 8);
  return {t.at(a, b), a >= 0 && b >= 0 && a + b <= 1};
}

// A height in (0, 1], in units of |n|.
double height() {
  return dyadic(1, 64, 6);
}

Generated make(const Triangle& t, const Vec3& b0, const Vec3& b1, Truth truth) {
  Generated g;
  g.query.x = {b0, t.d, t.e, t.f, b1, t.d, t.e, t.f};
  g.truth = truth;
  return g;
}

std::string ratio(long p, long q) {
  const long g = std::gcd(p, q);
  p /= g, q /= g;
  return q == 1 ? std::to_string(p) : std::to_string(p) + "/" + std::to_string(q);
}

// A path through X: B above the plane off to the side, B' = X - mu (B - X). It meets the
// plane only at X, at t = 1 / (1 + mu).
Generated through(const Triangle& t, const Vec3& x, Truth truth, const std::string& kind) {
  const Vec3 side = dyadic(-64, 64, 6) * (t.e - t.d) + dyadic(-64, 64, 6) * (t.f - t.d);
  const Vec3 b0 = x + dyadic(1, 64, 6) * t.n + side;
  const int mu = pick(1, 128);  // mu = mu/64
  Generated g = make(t, b0, x - std::ldexp(double(mu), -6) * (b0 - x), truth);
  if (truth == Truth::Yes) g.kind = kind, g.time = ratio(64, 64 + mu);
  return g;
}

Generated parallel_cross() {
  const Triangle t = gen_triangle();
  const InPlanePoint p = gen_in_plane(t);
  return make(t, p.x + height() * t.n, p.x - height() * t.n, truth_of(p.inside));
}

Generated parallel_short() {
  const Triangle t = gen_triangle();
  const InPlanePoint p = gen_in_plane(t);
  const double h0 = dyadic(2, 64, 6), h1 = dyadic(1, 63, 6) * h0;
  return make(t, p.x + h0 * t.n, p.x + h1 * t.n, Truth::No);
}

Generated parallel_land() {
  const Triangle t = gen_triangle();
  const InPlanePoint p = gen_in_plane(t);
  return make(t, p.x + height() * t.n, p.x, truth_of(p.inside));
}

Generated parallel_start() {
  const Triangle t = gen_triangle();
  const InPlanePoint p = gen_in_plane(t);
  const double s = *rc::gen::element(-1.0, 1.0);
  return make(t, p.x, p.x + s * height() * t.n, truth_of(p.inside));
}

Generated angled() {
  const Triangle t = gen_triangle();
  const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
  return make(t, p0.x + height() * t.n, p1.x + dyadic(-64, 64, 6) * t.n, Truth::Unknown);
}

Generated through_edge() {
  const Triangle t = gen_triangle();
  const int i = pick(0, 2);
  const Vec3 a = t.vertex(i), b = t.vertex((i + 1) % 3);
  return through(t, a + dyadic(1, 255, 8) * (b - a), Truth::Yes, "edge");
}

Generated through_vertex() {
  const Triangle t = gen_triangle();
  return through(t, t.vertex(pick(0, 2)), Truth::Yes, "vertex");
}

Generated hair_outside_edge() {
  const Triangle t = gen_triangle();
  // (V_{i+1} - V_i) × n points out of the triangle, in its plane.
  const int i = pick(0, 2);
  const Vec3 a = t.vertex(i), b = t.vertex((i + 1) % 3);
  const Vec3 out = cross(b - a, t.n);
  return through(t, a + dyadic(0, 256, 8) * (b - a) + 0x1p-30 * out, Truth::No, "");
}

Generated in_plane() {
  const Triangle t = gen_triangle();
  const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
  const Truth truth = (p0.inside || p1.inside) ? Truth::Yes : Truth::Unknown;
  Generated g = make(t, p0.x, p1.x, truth);
  if (truth == Truth::Yes) g.kind = "in-plane";
  return g;
}

Generated zero_motion() {
  const Triangle t = gen_triangle();
  const InPlanePoint p = gen_in_plane(t);
  const bool on_plane = *rc::gen::arbitrary<bool>();
  const Vec3 b = on_plane ? p.x : p.x + dyadic(-64, 64, 6) * t.n;
  return make(t, b, b, truth_of(b == p.x && p.inside));
}

Generated grazing() {
  const Triangle t = gen_triangle();
  const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
  const double s = *rc::gen::element(-1.0, 1.0);
  const double h = s * std::ldexp(1.0, -pick(20, 45));
  return make(t, p0.x + height() * t.n, p1.x + h * t.n, s > 0 ? Truth::No : Truth::Unknown);
}

Generated sliver() {
  Triangle s = gen_triangle();
  const Vec3 r = small_point(4);
  const Vec3 off = r == Vec3{} ? Vec3{0, 0, 1} : r;
  s.f = s.d + dyadic(-128, 384, 8) * (s.e - s.d) + std::ldexp(1.0, -pick(10, 40)) * off;
  s.n = cross(s.e - s.d, s.f - s.d);
  const Vec3 up = s.n == Vec3{} ? off : s.n;  // n may round to 0 for a thin enough sliver
  const InPlanePoint p0 = gen_in_plane(s), p1 = gen_in_plane(s);
  return make(s, p0.x + height() * up, p1.x - height() * up, Truth::Unknown);
}

// F on line DE, or all three corners at D. Half the paths go exactly through a point of the
// hull: the construction knows that hit, its kind and its time.
Generated degenerate() {
  Triangle s = gen_triangle();
  const bool point = pick(0, 3) == 0;
  if (point) s.e = s.d;
  s.f = s.d + dyadic(-128, 384, 8) * (s.e - s.d);
  s.n = Vec3{};
  if (*rc::gen::arbitrary<bool>()) return make(s, small_point(16), small_point(16), Truth::Unknown);
  // [D, E] lies in the hull. The path meets it only at t = 1 / (1 + mu), unless it runs
  // along the hull's line: then it enters earlier, and only the hit is certain.
  const Vec3 x = s.d + dyadic(0, 256, 8) * (s.e - s.d);
  Vec3 w = small_point(4);
  if (w == Vec3{}) w = Vec3{0, 0, 1};
  const int mu = pick(1, 128);
  Generated g = make(s, x + w, x - std::ldexp(double(mu), -6) * w, Truth::Yes);
  if (s.e == s.d || cross(w, s.e - s.d) != Vec3{}) g.time = ratio(64, 64 + mu);
  return g;
}

// The composite families start from one of these.
Generated any_base() {
  static Generated (*const kBases[])() = {
      parallel_cross, angled, through_edge, through_vertex, hair_outside_edge, grazing,
  };
  return kBases[pick(0, int(std::size(kBases)) - 1)]();
}

Generated far_from_origin() {
  Generated g = any_base();
  const int m = pick(20, 40);
  const Vec3 shift = std::ldexp(1.0, m) * small_point(4);
  bool exact = true;
  for (Vec3& p : g.query.x) {
    Vec3 s;
    exact &= add_exactly(p.x, shift.x, s.x) & add_exactly(p.y, shift.y, s.y) &
             add_exactly(p.z, shift.z, s.z);
    p = s;
  }
  if (!exact) g.truth = Truth::Unknown, g.kind.clear(), g.time.clear();
  return g;
}

Generated tiny() {
  Generated g = any_base();
  const int m = pick(20, 60);  // scaling by a power of two is exact: truth, kind, time all stay
  for (Vec3& p : g.query.x) p = std::ldexp(1.0, -m) * p;
  return g;
}

}  // namespace

std::vector<Family> static_families() {
  return {
      {"parallel-cross", false, "BB' along the normal, crossing the plane", parallel_cross},
      {"parallel-short", false, "BB' along the normal, stopping short of the plane",
       parallel_short},
      {"parallel-land", false, "BB' along the normal, landing exactly on the plane", parallel_land},
      {"parallel-start", false, "BB' along the normal, starting on the plane", parallel_start},
      {"angled", false, "at an angle to the normal, crossing or not", angled},
      {"through-edge", false, "through a point of an edge, exactly", through_edge},
      {"through-vertex", false, "through a vertex, exactly", through_vertex},
      {"hair-outside-edge", false, "through a point 2^-30 outside an edge", hair_outside_edge},
      {"in-plane", false, "the whole motion in the triangle's plane", in_plane},
      {"zero-motion", false, "B' = B", zero_motion},
      {"grazing", false, "B' ends 2^-20 to 2^-45 (times |n|) from the plane, on either side",
       grazing},
      {"far-from-origin", false,
       "a case of parallel-cross, angled, through-edge, through-vertex, hair-outside-edge or "
       "grazing, translated by up to 2^42",
       far_from_origin},
      {"tiny", false, "as far-from-origin, but scaled by 2^-20 to 2^-60 instead of translated",
       tiny},
      {"sliver", false, "F within 2^-10 to 2^-40 of line DE (never on it)", sliver},
      {"degenerate", false, "zero-area triangles: collinear or coincident corners", degenerate},
  };
}

}  // namespace fdh::verify

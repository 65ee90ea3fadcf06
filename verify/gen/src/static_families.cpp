#include "fdh/gen/static_families.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

struct Triangle {
  Vec3 d, e, f, n;  // n = DE × DF, exact for small integer vertices
  Vec3 vertex(int i) const { return i == 0 ? d : (i == 1 ? e : f); }
  // D + a DE + b DF: exact for a, b with few bits.
  Vec3 at(double a, double b) const { return d + a * (e - d) + b * (f - d); }
};

// An integer in [lo, hi] that shrinks toward the value nearest 0, alternating sides (c, c+1,
// c-1, c+2, ...), so that shrunk counterexamples have small coordinates rather than lo's.
int pick(int lo, int hi) {
  const int k = *rc::gen::inRange(0, hi - lo + 1);
  const int c = std::clamp(0, lo, hi), up = hi - c, down = c - lo, m = std::min(up, down);
  if (k <= 2 * m) return (k % 2) ? c + (k + 1) / 2 : c - k / 2;
  return up > down ? c + m + (k - 2 * m) : c - m - (k - 2 * m);
}
// A multiple of 2^-bits in [lo, hi] (lo, hi integers in units of 2^-bits).
double dyadic(int lo, int hi, int bits) {
  return std::ldexp(double(pick(lo, hi)), -bits);
}

Vec3 small_point(int r) {
  return Vec3{double(pick(-r, r)), double(pick(-r, r)), double(pick(-r, r))};
}

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

Generated make(Family f, const Triangle& t, const Vec3& b0, const Vec3& b1, int truth) {
  Generated g;
  g.family = f;
  g.query.id = family_name(f);
  g.query.x = {b0, t.d, t.e, t.f, b1, t.d, t.e, t.f};
  g.query.truth = truth;
  return g;
}

std::string ratio(long p, long q) {
  const long g = std::gcd(p, q);
  p /= g, q /= g;
  return q == 1 ? std::to_string(p) : std::to_string(p) + "/" + std::to_string(q);
}

// A path through X: B above the plane off to the side, B' = X - mu (B - X). It meets the
// plane only at X, at t = 1 / (1 + mu).
Generated through(Family f, const Triangle& t, const Vec3& x, int truth, const std::string& kind) {
  const Vec3 side = dyadic(-64, 64, 6) * (t.e - t.d) + dyadic(-64, 64, 6) * (t.f - t.d);
  const Vec3 b0 = x + dyadic(1, 64, 6) * t.n + side;
  const int mu = pick(1, 128);  // mu = mu/64
  Generated g = make(f, t, b0, x - std::ldexp(double(mu), -6) * (b0 - x), truth);
  if (truth == 1) g.kind = kind, g.time = ratio(64, 64 + mu);
  return g;
}

Generated gen_base(Family f) {
  const Triangle t = gen_triangle();
  const auto height = [] { return dyadic(1, 64, 6); };  // (0, 1] in units of |n|
  switch (f) {
    case Family::ParallelCross: {
      const InPlanePoint p = gen_in_plane(t);
      return make(f, t, p.x + height() * t.n, p.x - height() * t.n, p.inside);
    }
    case Family::ParallelShort: {
      const InPlanePoint p = gen_in_plane(t);
      const double h0 = dyadic(2, 64, 6), h1 = dyadic(1, 63, 6) * h0;
      return make(f, t, p.x + h0 * t.n, p.x + h1 * t.n, 0);
    }
    case Family::ParallelLand: {
      const InPlanePoint p = gen_in_plane(t);
      return make(f, t, p.x + height() * t.n, p.x, p.inside);
    }
    case Family::ParallelStart: {
      const InPlanePoint p = gen_in_plane(t);
      const double s = *rc::gen::element(-1.0, 1.0);
      return make(f, t, p.x, p.x + s * height() * t.n, p.inside);
    }
    case Family::Angled: {
      const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
      return make(f, t, p0.x + height() * t.n, p1.x + dyadic(-64, 64, 6) * t.n, -1);
    }
    case Family::ThroughEdge: {
      const int i = pick(0, 2);
      const Vec3 a = t.vertex(i), b = t.vertex((i + 1) % 3);
      return through(f, t, a + dyadic(1, 255, 8) * (b - a), 1, "edge");
    }
    case Family::ThroughVertex:
      return through(f, t, t.vertex(pick(0, 2)), 1, "vertex");
    case Family::HairOutsideEdge: {
      // (V_{i+1} - V_i) × n points out of the triangle, in its plane.
      const int i = pick(0, 2);
      const Vec3 a = t.vertex(i), b = t.vertex((i + 1) % 3);
      const Vec3 out = cross(b - a, t.n);
      return through(f, t, a + dyadic(0, 256, 8) * (b - a) + 0x1p-30 * out, 0, "");
    }
    case Family::InPlane: {
      const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
      const int truth = (p0.inside || p1.inside) ? 1 : -1;
      Generated g = make(f, t, p0.x, p1.x, truth);
      if (truth == 1) g.kind = "in-plane";
      return g;
    }
    case Family::ZeroMotion: {
      const InPlanePoint p = gen_in_plane(t);
      const bool on_plane = *rc::gen::arbitrary<bool>();
      const Vec3 b = on_plane ? p.x : p.x + dyadic(-64, 64, 6) * t.n;
      return make(f, t, b, b, (b == p.x) ? p.inside : 0);
    }
    case Family::Grazing: {
      const InPlanePoint p0 = gen_in_plane(t), p1 = gen_in_plane(t);
      const double s = *rc::gen::element(-1.0, 1.0);
      const double h = s * std::ldexp(1.0, -pick(20, 45));
      return make(f, t, p0.x + height() * t.n, p1.x + h * t.n, s > 0 ? 0 : -1);
    }
    case Family::Sliver: {
      Triangle s = t;
      const Vec3 r = small_point(4);
      const Vec3 off = r == Vec3{} ? Vec3{0, 0, 1} : r;
      s.f = s.d + dyadic(-128, 384, 8) * (s.e - s.d) + std::ldexp(1.0, -pick(10, 40)) * off;
      s.n = cross(s.e - s.d, s.f - s.d);
      const Vec3 up = s.n == Vec3{} ? off : s.n;  // n may round to 0 for a thin enough sliver
      const InPlanePoint p0 = gen_in_plane(s), p1 = gen_in_plane(s);
      return make(f, s, p0.x + height() * up, p1.x - height() * up, -1);
    }
    case Family::Degenerate: {
      // F on line DE, or all three corners at D. Half the paths go exactly through a point of
      // the hull: the construction knows that hit, its kind and its time.
      Triangle s = t;
      const bool point = pick(0, 3) == 0;
      if (point) s.e = s.d;
      s.f = s.d + dyadic(-128, 384, 8) * (s.e - s.d);
      s.n = Vec3{};
      if (*rc::gen::arbitrary<bool>()) return make(f, s, small_point(16), small_point(16), -1);
      // [D, E] lies in the hull. The path meets it only at t = 1 / (1 + mu), unless it runs
      // along the hull's line: then it enters earlier, and only the hit is certain.
      const Vec3 x = s.d + dyadic(0, 256, 8) * (s.e - s.d);
      Vec3 w = small_point(4);
      if (w == Vec3{}) w = Vec3{0, 0, 1};
      const int mu = pick(1, 128);
      Generated g = make(f, s, x + w, x - std::ldexp(double(mu), -6) * w, 1);
      if (s.e == s.d || cross(w, s.e - s.d) != Vec3{}) g.time = ratio(64, 64 + mu);
      return g;
    }
    default:
      break;
  }
  return make(f, t, t.d, t.d, -1);  // unreachable: the composite families are built below
}

const std::vector<Family> kBases = {Family::ParallelCross,   Family::Angled,
                                    Family::ThroughEdge,     Family::ThroughVertex,
                                    Family::HairOutsideEdge, Family::Grazing};

// a + b, and whether it was exact (Knuth's TwoSum error term is zero).
bool add_exactly(double a, double b, double& s) {
  s = a + b;
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb) == 0;
}

Generated gen_composite(Family f) {
  Generated g = gen_base(kBases[pick(0, int(kBases.size()) - 1)]);
  g.family = f;
  g.query.id = family_name(f);
  if (f == Family::Tiny) {  // scaling by a power of two is exact: truth, kind, time all stay
    const int m = pick(20, 60);
    for (Vec3& p : g.query.x) p = std::ldexp(1.0, -m) * p;
    return g;
  }
  const int m = pick(20, 40);
  const Vec3 shift = std::ldexp(1.0, m) * small_point(4);
  bool exact = true;
  for (Vec3& p : g.query.x) {
    Vec3 s;
    exact &= add_exactly(p.x, shift.x, s.x) & add_exactly(p.y, shift.y, s.y) &
             add_exactly(p.z, shift.z, s.z);
    p = s;
  }
  if (!exact) g.query.truth = -1, g.kind.clear(), g.time.clear();
  return g;
}

}  // namespace

const std::vector<Family>& all_families() {
  static const std::vector<Family> all = {
      Family::ParallelCross, Family::ParallelShort, Family::ParallelLand,  Family::ParallelStart,
      Family::Angled,        Family::ThroughEdge,   Family::ThroughVertex, Family::HairOutsideEdge,
      Family::InPlane,       Family::ZeroMotion,    Family::Grazing,       Family::FarFromOrigin,
      Family::Tiny,          Family::Sliver,        Family::Degenerate};
  return all;
}

std::string family_name(Family f) {
  switch (f) {
    case Family::ParallelCross:
      return "parallel-cross";
    case Family::ParallelShort:
      return "parallel-short";
    case Family::ParallelLand:
      return "parallel-land";
    case Family::ParallelStart:
      return "parallel-start";
    case Family::Angled:
      return "angled";
    case Family::ThroughEdge:
      return "through-edge";
    case Family::ThroughVertex:
      return "through-vertex";
    case Family::HairOutsideEdge:
      return "hair-outside-edge";
    case Family::InPlane:
      return "in-plane";
    case Family::ZeroMotion:
      return "zero-motion";
    case Family::Grazing:
      return "grazing";
    case Family::FarFromOrigin:
      return "far-from-origin";
    case Family::Tiny:
      return "tiny";
    case Family::Sliver:
      return "sliver";
    case Family::Degenerate:
      return "degenerate";
  }
  return "?";
}

std::optional<Family> family_by_name(const std::string& name) {
  for (Family f : all_families())
    if (family_name(f) == name) return f;
  return std::nullopt;
}

// RapidCheck scales inRange by its size parameter (size 0 gives only the minimum). A family is
// a fixed distribution, so every case is drawn at the nominal size; shrinking still works.
rc::Gen<Generated> gen_family(Family f) {
  return rc::gen::resize(
      rc::kNominalSize, rc::gen::exec([f] {
        return (f == Family::FarFromOrigin || f == Family::Tiny) ? gen_composite(f) : gen_base(f);
      }));
}

rc::Gen<Soup> gen_soup(int max_tris) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([max_tris] {
                           Soup s;
                           const int n = pick(1, max_tris);
                           const auto coord = [] { return dyadic(-64, 64, 3); };
                           const auto step = [] { return dyadic(-8, 8, 4); };
                           for (int t = 0; t < n; ++t) {
                             Tri tri;
                             for (int& corner : tri) {
                               if (!s.x0.empty() && pick(0, 3) == 3) {
                                 corner = pick(0, int(s.x0.size()) - 1);
                               } else {
                                 corner = int(s.x0.size());
                                 const Vec3 p{coord(), coord(), coord()};
                                 s.x0.push_back(p);
                                 s.x1.push_back(p + Vec3{step(), step(), step()});
                               }
                             }
                             s.tris.push_back(tri);
                           }
                           return s;
                         }));
}

std::vector<std::vector<Vec3>> primitive_corners(const std::vector<Tri>& tris,
                                                 const std::vector<Vec3>& x0,
                                                 const std::vector<Vec3>& x1) {
  std::vector<std::vector<Vec3>> out;
  for (const Tri& t : tris) {
    std::vector<Vec3> pts;
    for (const int v : t) {
      pts.push_back(x0[v]);
      if (!x1.empty()) pts.push_back(x1[v]);
    }
    out.push_back(pts);
  }
  return out;
}

void showValue(const Generated& g, std::ostream& os) {
  os << family_name(g.family) << " (truth " << g.query.truth << ")\n";
  write_native(os, g.query);
}

}  // namespace fdh::verify

// The minimum-separation families (issue 30): queries at δ > 0 whose minimum distance the
// construction knows exactly. Most take a pair at its closest, A and B at distance exactly
// D = 5u (u a power of two; offsets (3u, 4u) and (0, 5u) are Pythagorean, so D is exact), and
// move B away along the offset n from A's closest point to B's: B + k(1 - t) n is at distance
// D (1 + k (1 - t)) from A, because A lies on the far side of the plane through A's closest
// point normal to n. A common velocity, time reversal, a signed permutation of the axes, a
// dyadic translation and a power-of-two scale (of D too) change no distance. δ is then D or
// D (1 ± 2^-40), both exact doubles: a hit iff δ >= D. The table at the end is their registry.
#include <array>
#include <cmath>
#include <utility>

#include "constructions.hpp"
#include "draw.hpp"

namespace fdh::verify {
namespace {

int in(int lo, int hi) {
  return *rc::gen::inRange(lo, hi + 1);
}
bool coin() {
  return *rc::gen::arbitrary<bool>();
}

// A pair at its closest: vf (v, f0, f1, f2) or ee (a0, a1, b0, b1); B is v or edge b; n goes
// from A's closest point to B's, |n| = d.
struct Closest {
  QueryKind kind = QueryKind::VertexFace;
  std::array<Vec3, 4> x{};
  Vec3 n;
  double d = 0;
};

// The right triangle (0,0,0), (lx,0,0), (0,ly,0) and v = its closest point + n, n in the normal
// cone of the feature: the face (n = (0,0,5u)), edge ab (n = (0,-3u,±4u), the triangle lies at
// y >= 0), edge ac, vertex a ((-3u,-4u,0): x, y <= 0) or vertex b ((3u,-4u,0)).
Closest vertex_face(double u, int lx, int ly) {
  const double x = double(lx), y = double(ly), s = coin() ? 1 : -1;
  const Vec3 a{0, 0, 0}, b{x, 0, 0}, c{0, y, 0};
  Vec3 at, n;
  switch (in(0, 4)) {
    case 0:
      at = {x / 4, y / 4, 0}, n = {0, 0, s * 5 * u};
      break;
    case 1:
      at = {dyadic(0, 4 * lx, 2), 0, 0}, n = {0, -3 * u, s * 4 * u};
      break;
    case 2:
      at = {0, dyadic(0, 4 * ly, 2), 0}, n = {-3 * u, 0, s * 4 * u};
      break;
    case 3:
      at = a, n = {-3 * u, -4 * u, 0};
      break;
    default:
      at = b, n = {3 * u, -4 * u, 0};
  }
  return {QueryKind::VertexFace, {at + n, a, b, c}, n, 5 * u};
}

// Edge a from the origin to (la,0,0); edge b: across it (interior-interior, b's direction
// (bx,4m,3m) normal to n = (0,-3u,4u)), parallel to it (m = 0), from its end b0 outward along
// (bx,-3m,4m) (end-interior), or beyond a's end (-3u,0,4u) (end-end: b keeps x < 0).
Closest edge_edge(double u, int la, bool parallel) {
  const double l = double(la), pa = dyadic(0, 4 * la, 2), bx = double(in(-4, 4));
  const double m = parallel ? 0 : double(in(bx == 0 ? 1 : 0, 4));
  const Vec3 a0{0, 0, 0}, a1{l, 0, 0};
  const int feature = parallel ? 0 : in(0, 2);
  if (feature == 0) {
    const Vec3 n{0, -3 * u, 4 * u}, e{parallel && bx == 0 ? 1 : bx, 4 * m, 3 * m};
    return {
        QueryKind::EdgeEdge, {a0, a1, Vec3{pa, 0, 0} + n - e, Vec3{pa, 0, 0} + n + e}, n, 5 * u};
  }
  if (feature == 1) {
    const Vec3 n{0, -3 * u, 4 * u}, b0 = Vec3{pa, 0, 0} + n;
    return {QueryKind::EdgeEdge, {a0, a1, b0, b0 + Vec3{bx, -3 * m, 4 * m}}, n, 5 * u};
  }
  const Vec3 n{-3 * u, 0, 4 * u};
  return {QueryKind::EdgeEdge, {a0, a1, n, n + Vec3{-3 * m, bx, 4 * m}}, n, 5 * u};
}

// Degenerate primitives, the closed sets they are: a triangle that is a segment or a point,
// an edge that is a point (one or both).
Closest degenerate(double u, int l) {
  const double x = double(l);
  switch (in(0, 3)) {
    case 0: {  // the triangle is the segment ab (c = b): v beside it, either side
      const Vec3 n{0, coin() ? 3 * u : -3 * u, 4 * u}, at{dyadic(0, 4 * l, 2), 0, 0};
      return {QueryKind::VertexFace, {at + n, {0, 0, 0}, {x, 0, 0}, {x, 0, 0}}, n, 5 * u};
    }
    case 1: {  // the triangle is a point
      const Vec3 n{3 * u, 4 * u, 0}, p{x, x, 0};
      return {QueryKind::VertexFace, {p + n, p, p, p}, n, 5 * u};
    }
    case 2: {  // edge a is a point, b across it
      const Vec3 n{0, -3 * u, 4 * u}, e{double(in(-4, 4)), 4, 3};
      return {QueryKind::EdgeEdge, {Vec3{}, Vec3{}, n - e, n + e}, n, 5 * u};
    }
    default: {  // both edges are points
      const Vec3 n{0, 3 * u, 4 * u};
      return {QueryKind::EdgeEdge, {Vec3{}, Vec3{}, n, n}, n, 5 * u};
    }
  }
}

// A signed permutation of the axes, a dyadic translation and a power-of-two scale (of δ too):
// no distance changes but by the scale.
void reframe(Query& q, int max_scale) {
  static const int p[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int perm = in(0, 5), scale = in(-max_scale, max_scale);
  const Vec3 sign{double(2 * in(0, 1) - 1), double(2 * in(0, 1) - 1), double(2 * in(0, 1) - 1)};
  const Vec3 shift = small_point(16);
  for (Vec3& v : q.x) {
    const double c[3] = {v.x, v.y, v.z};
    const Vec3 w{c[p[perm][0]] * sign.x, c[p[perm][1]] * sign.y, c[p[perm][2]] * sign.z};
    v = std::ldexp(1.0, scale) * (w + shift);
  }
  q.min_distance = std::ldexp(q.min_distance, scale);
}

// δ = D (1 - 2^-40), D or D (1 + 2^-40): exact for D = 5u. A hit iff δ >= D.
double delta_near(double d, int which) {
  return which == 1 ? d : d + (which == 0 ? -1 : 1) * std::ldexp(d, -40);
}

// The pair moved as the header says: B at k (1 - t) n off its closest (k = 0: it stays), the
// whole pair moving by `velocity`, the step reversed or not; then reframed.
Generated approach(const Closest& c, bool moving_pair, int max_scale) {
  static const double ks[5] = {0, 0.25, 0.5, 1, 2};
  const double k = ks[in(0, 4)];
  Vec3 velocity = moving_pair ? small_point(4) : Vec3{};
  if (moving_pair && velocity == Vec3{}) velocity = {1, 0, 0};  // a moving pair moves
  const int b_from = c.kind == QueryKind::VertexFace ? 0 : 2, b_to = b_from == 0 ? 1 : 4;
  Generated g;
  g.query.kind = c.kind;
  for (int i = 0; i < 4; ++i) {
    const bool b = i >= b_from && i < b_to;
    g.query.x[i] = c.x[i] + (b ? k * c.n : Vec3{});
    g.query.x[i + 4] = c.x[i] + velocity;
  }
  const bool reversed = coin();
  if (reversed)
    for (int i = 0; i < 4; ++i) std::swap(g.query.x[i], g.query.x[i + 4]);
  const int which = in(0, 2);
  g.query.min_distance = delta_near(c.d, which);
  g.truth = truth_of(which >= 1);
  // At δ = D the earliest time within δ is where B is at its closest.
  if (which == 1) g.time = k == 0 || reversed ? "0" : "1";
  reframe(g.query, max_scale);
  return g;
}

double unit(int lo, int hi) {
  return std::ldexp(1.0, in(lo, hi));
}

Generated still() {
  return approach(vertex_face(unit(-30, 4), in(1, 16), in(1, 16)), false, 20);
}

Generated moving_vertex_face() {
  return approach(vertex_face(unit(-30, 4), in(1, 16), in(1, 16)), true, 20);
}

Generated edges() {
  return approach(edge_edge(unit(-30, 4), in(1, 16), false), true, 20);
}

Generated parallel() {
  return approach(edge_edge(unit(-30, 4), in(1, 16), true), true, 20);
}

// D = 5u with u from 2^4 to 2^12, the primitives at most 4 long.
Generated large() {
  const double u = unit(4, 12);
  const Closest c = coin() ? vertex_face(u, in(1, 4), in(1, 4)) : edge_edge(u, in(1, 4), false);
  return approach(c, true, 20);
}

Generated degenerate_primitives() {
  return approach(degenerate(unit(-30, 4), in(1, 16)), true, 20);
}

// The static query for a still right triangle (0,0,0), (lx,0,0), (0,ly,0): v's path and δ.
Generated still_query(const Vec3& v0, const Vec3& v1, int lx, int ly, double delta, bool hit) {
  Generated g;
  g.query.x = {v0, {0, 0, 0}, {double(lx), 0, 0}, {0, double(ly), 0},
               v1, {0, 0, 0}, {double(lx), 0, 0}, {0, double(ly), 0}};
  g.query.min_distance = delta;
  g.truth = truth_of(hit);
  reframe(g.query, 20);
  return g;
}

// A vertex sliding at height ±D over the plane of a still triangle: through (lx/4, ly/4) at
// t = 1/2 (minimum distance D), or along y = -1/4, beside the triangle (at least
// sqrt(D^2 + 1/16) > D (1 + 2^-40), as D <= 20).
Generated sliding() {
  const int lx = in(1, 16), ly = in(1, 16), which = in(0, 2);
  const double d = 5 * unit(-30, 2), h = coin() ? d : -d;
  const double vx = double(in(-16, 16)), vy = double(in(-16, 16));
  const bool over = coin();
  const Vec3 mid = over ? Vec3{lx / 4.0, ly / 4.0, h} : Vec3{lx / 4.0, -0.25, h};
  const Vec3 half{vx / 2, over ? vy / 2 : 0, 0};
  return still_query(mid - half, mid + half, lx, ly, delta_near(d, which), over && which >= 1);
}

// Past vertex (0,0,0) of a still triangle, in its normal cone (x, y <= 0): v(t) = (-s, -y0,
// z0 (1 - 2t)) is at squared distance s^2 + y0^2 + z0^2 (1 - 2t)^2. With s^2 + y0^2 <= 18 < 25
// = D^2 it dips below D = 5 first at t = (z0 - sqrt(25 - s^2 - y0^2)) / (2 z0), irrational (25 -
// s^2 - y0^2 is no square); with s^2 + y0^2 >= 26 it stays farther than D (1 + 2^-40).
Generated irrational_dip() {
  static const int pass[3][2] = {{4, 4}, {5, 1}, {3, 5}};
  const bool dip = coin();
  const int k = in(0, 2), s = dip ? in(1, 3) : pass[k][0], y0 = dip ? in(1, 3) : pass[k][1];
  const double z0 = double(in(6, 12));
  const int which = in(0, 2);
  const Vec3 v0{-double(s), -double(y0), z0}, v1{-double(s), -double(y0), -z0};
  return still_query(v0, v1, in(1, 16), in(1, 16), delta_near(5, which), dip);
}

}  // namespace

std::vector<Family> min_distance_families() {
  return {
      {"delta-still", false,
       "δ: a still triangle, the vertex at distance exactly D from its face, an edge or a "
       "vertex; δ = D or D (1 ± 2^-40)",
       still},
      {"delta-vertex-face", true,
       "δ: a moving triangle, the vertex at distance exactly D from its face, an edge or a "
       "vertex at its closest; δ = D or D (1 ± 2^-40)",
       moving_vertex_face},
      {"delta-edge-edge", true,
       "δ: two moving edges at distance exactly D, interior to interior, end to interior or end "
       "to end; δ = D or D (1 ± 2^-40)",
       edges},
      {"delta-parallel-edges", true,
       "δ: parallel edges at distance exactly D; δ = D or D (1 ± 2^-40)", parallel},
      {"delta-sliding", false,
       "δ: a vertex sliding at height D over a still triangle's plane, over the face or beside "
       "it",
       sliding},
      {"delta-irrational", false,
       "δ: the vertex dips below D past a still triangle's corner, first at an irrational time, "
       "or passes farther",
       irrational_dip},
      {"delta-large", true, "δ: D = 80 to 20480 times larger than primitives 1 to 4 long", large},
      {"delta-degenerate", true,
       "δ: a triangle that is a segment or a point, edges that are points, at distance exactly D",
       degenerate_primitives},
  };
}

}  // namespace fdh::verify

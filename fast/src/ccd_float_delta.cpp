// float-cubic within δ (q.min_distance > 0): the naive floating-point baseline of issue 30, the
// way it is commonly written. Each closest feature pair gives a polynomial in t whose sign says
// "within δ" (squared distances against δ², denominators multiplied out):
//   vertex-face: the plane, f² - δ² |n|² (degree 6); each side, |(p - a) x e|² - δ² |e|² (4);
//                each corner, |p - a|² - δ² (2);
//   edge-edge:   the lines, f² - δ² |ea x eb|² (6); each end against the other edge (4); each
//                pair of ends (2).
// Their roots in [0, 1] are found in doubles (by the roots of the derivative, then bisection),
// and at each, in time order, the feature's region is tested in doubles with no tolerance: the
// first that passes is the time. Not exact, on purpose: its misses and false alarms are what
// `robust` within δ exists to remove.
#include "ccd_float_delta.hpp"

#include <algorithm>
#include <cmath>

namespace fdh {
namespace {

// A polynomial of degree <= 6 in t; c[i] multiplies t^i.
struct Poly {
  double c[7] = {0, 0, 0, 0, 0, 0, 0};
  int deg = 0;
  double operator()(double t) const {
    double v = 0;
    for (int i = deg; i >= 0; --i) v = v * t + c[i];
    return v;
  }
};
Poly operator+(const Poly& a, const Poly& b) {
  Poly r;
  r.deg = std::max(a.deg, b.deg);
  for (int i = 0; i <= r.deg; ++i) r.c[i] = a.c[i] + b.c[i];
  return r;
}
Poly operator*(const Poly& a, const Poly& b) {
  Poly r;
  r.deg = a.deg + b.deg;
  for (int i = 0; i <= a.deg; ++i)
    for (int j = 0; j <= b.deg; ++j) r.c[i + j] += a.c[i] * b.c[j];
  return r;
}
Poly scaled(double s, const Poly& a) {
  Poly r = a;
  for (double& x : r.c) x *= s;
  return r;
}
Poly derivative(const Poly& a) {
  Poly r;
  r.deg = std::max(0, a.deg - 1);
  for (int i = 1; i <= a.deg; ++i) r.c[i - 1] = i * a.c[i];
  return r;
}

struct PV {  // a vector of polynomials
  Poly x, y, z;
};
PV operator-(const PV& a, const PV& b) {
  return {a.x + scaled(-1, b.x), a.y + scaled(-1, b.y), a.z + scaled(-1, b.z)};
}
Poly dot(const PV& a, const PV& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
PV cross(const PV& a, const PV& b) {
  return {a.y * b.z + scaled(-1, a.z * b.y), a.z * b.x + scaled(-1, a.x * b.z),
          a.x * b.y + scaled(-1, a.y * b.x)};
}
PV motion(const Vec3& x0, const Vec3& x1) {
  const auto lin = [](double a, double b) {
    Poly p;
    p.c[0] = a, p.c[1] = b - a, p.deg = 1;
    return p;
  };
  return {lin(x0.x, x1.x), lin(x0.y, x1.y), lin(x0.z, x1.z)};
}

// The roots in [0, 1], increasing, at most 6: the derivative's split [0, 1] into monotone
// pieces, each sign change bisected.
int roots_in_unit(const Poly& p, double out[7]) {
  double cuts[8];
  int nc = 0;
  cuts[nc++] = 0;
  if (p.deg >= 2) {
    double inner[7];
    const int n = roots_in_unit(derivative(p), inner);
    for (int i = 0; i < n; ++i)
      if (inner[i] > 0 && inner[i] < 1) cuts[nc++] = inner[i];
  }
  cuts[nc++] = 1;
  int n = 0;
  for (int i = 0; i + 1 < nc; ++i) {
    double lo = cuts[i], hi = cuts[i + 1];
    const double flo = p(lo), fhi = p(hi);
    if (flo == 0) {
      if (n == 0 || out[n - 1] != lo) out[n++] = lo;
      continue;
    }
    if (fhi == 0 || (flo < 0) == (fhi < 0)) continue;
    for (int it = 0; it < 64; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      ((p(mid) < 0) == (flo < 0) ? lo : hi) = mid;
    }
    out[n++] = 0.5 * (lo + hi);
  }
  if (p(1) == 0 && (n == 0 || out[n - 1] != 1)) out[n++] = 1;
  return std::min(n, 6);
}

// ---- The features and their regions, in doubles at one time.

Vec3 at(const Vec3& x0, const Vec3& x1, double t) {
  return x0 + t * (x1 - x0);
}
bool in_unit(double s) {
  return s >= 0 && s <= 1;
}

// A feature: its polynomial, and whether its closest pair lies in its region at a time.
struct Feature {
  Poly g;       // <= 0: within δ of the feature's carrier (plane, line, point)
  int kind;     // 0: plane or lines, 1: a point against a line, 2: two points
  int i, j, k;  // the points it involves (x[i] against x[j] x[k], ...)
};

bool in_region(const Query& q, const Feature& f, double t) {
  Vec3 x[4];
  for (int i = 0; i < 4; ++i) x[i] = at(q.x[i], q.x[i + 4], t);
  if (f.kind == 2) return true;
  if (f.kind == 1) {  // x[i] against the line x[j] x[k]: its projection inside the segment
    const Vec3 e = x[f.k] - x[f.j];
    const double ee = dot(e, e);
    return ee > 0 && in_unit(dot(x[f.i] - x[f.j], e) / ee);
  }
  if (q.kind == QueryKind::VertexFace) {  // the projection inside the triangle, by its sides
    const Vec3 n = cross(x[2] - x[1], x[3] - x[1]);
    return dot(n, n) > 0 && dot(cross(x[2] - x[1], x[0] - x[1]), n) >= 0 &&
           dot(cross(x[3] - x[2], x[0] - x[2]), n) >= 0 &&
           dot(cross(x[1] - x[3], x[0] - x[3]), n) >= 0;
  }
  // Both closest-point parameters of the two lines inside their segments.
  const Vec3 ea = x[1] - x[0], eb = x[3] - x[2], w = x[0] - x[2];
  const double a = dot(ea, ea), b = dot(ea, eb), e = dot(eb, eb), d = dot(ea, w), c = dot(eb, w);
  const double den = a * e - b * b;
  return den > 0 && in_unit((b * c - d * e) / den) && in_unit((a * c - b * d) / den);
}

// Point i against the line j k: |(x_i - x_j) x e|² - δ² |e|², e = x_k - x_j.
Feature point_line(const PV x[4], double d2, int i, int j, int k) {
  const PV e = x[k] - x[j], c = cross(x[i] - x[j], e);
  return {dot(c, c) + scaled(-d2, dot(e, e)), 1, i, j, k};
}
Feature point_point(const PV x[4], double d2, int i, int j) {
  const PV d = x[i] - x[j];
  Poly g = dot(d, d);
  g.c[0] -= d2;
  return {g, 2, i, j, j};
}

int features(const Query& q, Feature out[10]) {
  PV x[4];
  for (int i = 0; i < 4; ++i) x[i] = motion(q.x[i], q.x[i + 4]);
  const double d2 = q.min_distance * q.min_distance;
  int n = 0;
  if (q.kind == QueryKind::VertexFace) {
    const PV nrm = cross(x[2] - x[1], x[3] - x[1]);
    const Poly f = dot(x[1] - x[0], nrm);
    out[n++] = {f * f + scaled(-d2, dot(nrm, nrm)), 0, 0, 0, 0};
    out[n++] = point_line(x, d2, 0, 1, 2), out[n++] = point_line(x, d2, 0, 2, 3);
    out[n++] = point_line(x, d2, 0, 3, 1);
    for (int j = 1; j <= 3; ++j) out[n++] = point_point(x, d2, 0, j);
    return n;
  }
  const PV m = cross(x[1] - x[0], x[3] - x[2]);
  const Poly f = dot(x[2] - x[0], m);
  out[n++] = {f * f + scaled(-d2, dot(m, m)), 0, 0, 0, 0};
  out[n++] = point_line(x, d2, 0, 2, 3), out[n++] = point_line(x, d2, 1, 2, 3);
  out[n++] = point_line(x, d2, 2, 0, 1), out[n++] = point_line(x, d2, 3, 0, 1);
  for (int i = 0; i <= 1; ++i)
    for (int j = 2; j <= 3; ++j) out[n++] = point_point(x, d2, i, j);
  return n;
}

}  // namespace

Toi float_first_within(const Query& q) {
  Feature fs[10];
  const int nf = features(q, fs);
  double best = 2;
  for (int i = 0; i < nf; ++i) {
    double roots[7];
    const int n = roots_in_unit(fs[i].g, roots);
    // A feature already within δ at t = 0 counts from there.
    for (int r = 0; r < n && roots[r] < best; ++r)
      if (in_region(q, fs[i], roots[r])) best = roots[r];
    if (fs[i].g(0) < 0 && in_region(q, fs[i], 0)) best = 0;
  }
  return best <= 1 ? Toi{true, best, best} : Toi{};
}

}  // namespace fdh

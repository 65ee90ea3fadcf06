#include "fdh/ccd/float_cubic.hpp"

#include "ccd_float_delta.hpp"
#include "fdh/ccd/toi.hpp"

#include <algorithm>
#include <cmath>

namespace fdh {
namespace {

double det(const Vec3& u, const Vec3& v, const Vec3& w) {
  return dot(u, cross(v, w));
}

Vec3 at(const Vec3& x0, const Vec3& x1, double t) {
  return x0 + t * (x1 - x0);
}

struct Cubic {
  double c[4];  // c[i] multiplies t^i
  double operator()(double t) const { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
};

// det(U(t), V(t), W(t)) for U(t) = U0 + t dU and so on, expanded by multilinearity.
Cubic coplanarity(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1, const Vec3& w0,
                  const Vec3& w1) {
  const Vec3 du = u1 - u0, dv = v1 - v0, dw = w1 - w0;
  return {{det(u0, v0, w0), det(du, v0, w0) + det(u0, dv, w0) + det(u0, v0, dw),
           det(du, dv, w0) + det(du, v0, dw) + det(u0, dv, dw), det(du, dv, dw)}};
}

// The roots in [0, 1], increasing: split at the critical points, bisect each sign change.
int roots_in_unit(const Cubic& f, double out[3]) {
  double cuts[4] = {0, 0, 0, 0};
  int nc = 0;
  const double a = 3 * f.c[3], b = 2 * f.c[2], c = f.c[1];  // f' = a t^2 + b t + c
  if (a != 0) {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double s = std::sqrt(disc);
      cuts[nc++] = (-b - s) / (2 * a);
      cuts[nc++] = (-b + s) / (2 * a);
    }
  } else if (b != 0) {
    cuts[nc++] = -c / b;
  }
  double pts[4] = {0, 0, 0, 0};
  int np = 0;
  pts[np++] = 0;
  std::sort(cuts, cuts + nc);
  for (int i = 0; i < nc; ++i)
    if (cuts[i] > 0 && cuts[i] < 1) pts[np++] = cuts[i];
  pts[np++] = 1;
  int n = 0;
  for (int i = 0; i + 1 < np; ++i) {
    double lo = pts[i], hi = pts[i + 1], flo = f(lo), fhi = f(hi);
    if (flo == 0) {
      if (n == 0 || out[n - 1] != lo) out[n++] = lo;
      continue;
    }
    if (fhi == 0 || (flo < 0) == (fhi < 0)) continue;
    for (int it = 0; it < 64; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const double fm = f(mid);
      if (fm == 0) {
        lo = hi = mid;
        break;
      }
      ((fm < 0) == (flo < 0) ? lo : hi) = mid;
    }
    out[n++] = 0.5 * (lo + hi);
    if (n == 3) break;
  }
  if (n < 3 && f(1) == 0 && (n == 0 || out[n - 1] != 1)) out[n++] = 1;
  return n;
}

// Barycentric coordinates by the normal equations (Ericson, Real-Time Collision Detection, 3.4).
bool inside_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
  const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
  const double d20 = dot(v2, v0), d21 = dot(v2, v1);
  const double denom = d00 * d11 - d01 * d01;
  if (denom == 0) return false;
  const double v = (d11 * d20 - d01 * d21) / denom, w = (d00 * d21 - d01 * d20) / denom;
  return v >= 0 && w >= 0 && v + w <= 1;
}

// Coplanar segments: a0 + s ea = b0 + u eb, solved with m = ea x eb.
bool segments_meet(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 ea = a1 - a0, eb = b1 - b0, w = b0 - a0, m = cross(ea, eb);
  const double mm = dot(m, m);
  if (mm == 0) return false;
  const double s = dot(cross(w, eb), m) / mm, u = dot(cross(w, ea), m) / mm;
  return s >= 0 && s <= 1 && u >= 0 && u <= 1;
}

bool touch_at(const Query& q, double t) {
  const auto& x = q.x;
  const Vec3 p0 = at(x[0], x[4], t), p1 = at(x[1], x[5], t), p2 = at(x[2], x[6], t),
             p3 = at(x[3], x[7], t);
  return q.kind == QueryKind::VertexFace ? inside_triangle(p0, p1, p2, p3)
                                         : segments_meet(p0, p1, p2, p3);
}

// The first root in [0, 1] at which the primitives touch (time order), or none.
Toi first_touch(const Query& q) {
  if (q.min_distance > 0) return float_first_within(q);  // the baseline within δ
  const auto& x = q.x;
  // Both kinds: det(x1 - x0, x2 - x0, x3 - x0), i.e. (a-p, b-p, c-p) or (ea1-ea0, eb0-ea0,
  // eb1-ea0).
  const Cubic f =
      coplanarity(x[1] - x[0], x[5] - x[4], x[2] - x[0], x[6] - x[4], x[3] - x[0], x[7] - x[4]);
  if (f.c[0] == 0 && f.c[1] == 0 && f.c[2] == 0 && f.c[3] == 0) {
    for (const double t : {0.0, 1.0})
      if (touch_at(q, t)) return {true, t, t};
    return {};
  }
  double roots[3];
  const int n = roots_in_unit(f, roots);
  for (int i = 0; i < n; ++i)
    if (touch_at(q, roots[i])) return {true, roots[i], roots[i]};
  return {};
}

}  // namespace

bool float_cubic(const Query& q) {
  return first_touch(q).hit;
}

Toi float_cubic_toi(const Query& q) {
  return first_touch(q);
}

}  // namespace fdh

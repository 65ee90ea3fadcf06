// The contact conditions of a moving query at a time, in floating point or over a time interval,
// and what intervals make certain of them: shared by `robust`'s subdivision (ccd_robust.cpp) and
// its integer stage (ccd_robust_integer.cpp). Private to fast/.
#pragma once

#include "fdh/interval.hpp"
#include "fdh/query.hpp"
#include "motion.hpp"

namespace fdh::ccd_conditions {

using namespace motion;

// The conditions g_i over a time interval. At a coplanar time, contact iff every g_i >= 0 (the
// same polynomials as reference/'s exact_ccd.cpp); g_i > 0 for all i implies contact, since the
// g_i all vanish when the triangle has zero area or the edges are parallel. (f itself is
// bounded on pieces by its Bernstein coefficients, not here.)
template <class T>
struct Conditions {
  T g[4];
  int n = 0;
};

template <class T>
inline Conditions<T> vertex_face(const Query& q, const T& t) {
  const V3<T> p = at(q.x[0], q.x[4], t), a = at(q.x[1], q.x[5], t), b = at(q.x[2], q.x[6], t),
              c = at(q.x[3], q.x[7], t);
  const V3<T> ap = a - p, bp = b - p, cp = c - p, n = cross(b - a, c - a);
  // |n|^2 times p's barycentric coordinates when coplanar.
  return {{dot(n, cross(bp, cp)), dot(n, cross(cp, ap)), dot(n, cross(ap, bp))}, 3};
}

template <class T>
inline Conditions<T> edge_edge(const Query& q, const T& t) {
  const V3<T> a0 = at(q.x[0], q.x[4], t), a1 = at(q.x[1], q.x[5], t), b0 = at(q.x[2], q.x[6], t),
              b1 = at(q.x[3], q.x[7], t);
  const V3<T> ea = a1 - a0, eb = b1 - b0, w = b0 - a0, m = cross(ea, eb);
  const T mm = dot(m, m), s = dot(cross(w, eb), m), u = dot(cross(w, ea), m);
  // a0 + (s/mm) ea = b0 + (u/mm) eb when coplanar: both parameters in [0, 1].
  return {{s, mm - s, u, mm - u}, 4};
}

template <class T>
inline Conditions<T> conditions_at(const Query& q, const T& t) {
  return q.kind == QueryKind::VertexFace ? vertex_face(q, t) : edge_edge(q, t);
}

// What the intervals make certain: some g_i < 0 (out: no contact there), every g_i > 0 (inside:
// a contact, given coplanarity).
struct Signs {
  bool out = false, inside = true;
};
inline Signs certain_signs(const Conditions<Interval>& c) {
  Signs r;
  for (int i = 0; i < c.n; ++i) r.out |= c.g[i].negative(), r.inside &= c.g[i].positive();
  return r;
}

}  // namespace fdh::ccd_conditions

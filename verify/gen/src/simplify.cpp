// Shrinking's second greedy pass: plain simplifications of a failing query (simplify.hpp).
#include "fdh/gen/simplify.hpp"

#include "fdh/dyadic.hpp"
#include "fdh/gen/short_doubles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace fdh::verify {
namespace {

double& coord(Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

// The query with `shift` added to the points in [from, to), when every sum is exact.
bool shifted(Query& q, const Vec3& shift, int from, int to) {
  for (int i = from; i < to; ++i)
    for (int a = 0; a < 3; ++a)
      if (!add_exactly(q.x[i][a], shift[a], coord(q.x[i], a))) return false;
  return true;
}

// Vertex groups that move together: the point and the triangle, or the two edges.
std::vector<std::vector<int>> groups(const Query& q) {
  if (q.kind == QueryKind::VertexFace) return {{0}, {1, 2, 3}};
  return {{0, 1}, {2, 3}};
}

// A group's vertices, then each vertex, stopped at its start or at its end position.
void stop_motion(const Query& q, std::vector<Query>& out) {
  std::vector<std::vector<int>> sets = groups(q);
  for (int i = 0; i < 4; ++i) sets.push_back({i});
  for (const std::vector<int>& set : sets)
    for (const bool at_start : {true, false}) {
      Query c = q;
      for (const int i : set) (at_start ? c.x[i + 4] : c.x[i]) = at_start ? q.x[i] : q.x[i + 4];
      out.push_back(std::move(c));
    }
  for (int i = 0; i < 4; ++i)  // motion along one axis stopped
    for (int a = 0; a < 3; ++a) {
      Query c = q;
      coord(c.x[i + 4], a) = q.x[i][a];
      out.push_back(std::move(c));
    }
}

// A common velocity taken out (vertex i then stands still), a common translation that puts a
// point or one of its coordinates at 0, and scales by powers of two: contacts and their times
// do not change under these.
void change_frame(const Query& q, std::vector<Query>& out) {
  for (int i = 0; i < 4; ++i) {
    Query c = q;
    const Vec3 v = q.x[i + 4] - q.x[i];
    if (q.x[i + 4] - v == q.x[i] && v != Vec3{} && shifted(c, -v, 4, 8)) out.push_back(c);
  }
  for (int i = 0; i < 8; ++i)
    for (int a = -1; a < 3; ++a) {  // -1: every axis
      Vec3 t = a < 0 ? q.x[i] : Vec3{};
      if (a >= 0) coord(t, a) = q.x[i][a];
      for (const Vec3& s : {t, Vec3{std::trunc(t.x), std::trunc(t.y), std::trunc(t.z)}}) {
        Query c = q;
        if (s != Vec3{} && shifted(c, -s, 0, 8)) out.push_back(c);
      }
    }
  double top = 0;
  for (const Vec3& p : q.x) top = std::fmax(top, max_abs(p));
  int e = 0;
  std::frexp(top, &e);
  for (const int s : {1 - e, -1, 1}) {
    Query c = q;
    bool exact = s != 0 && top > 0;
    for (Vec3& p : c.x)
      for (int a = 0; a < 3 && exact; ++a) exact = scale_exactly(p[a], s, coord(p, a));
    // δ is a distance: it scales with the points, so the question stays the same.
    exact = exact && scale_exactly(q.min_distance, s, c.min_distance);
    if (exact) out.push_back(std::move(c));
  }
}

// Each coordinate replaced by 0, by its integer part, or by its top 1, 2, 4, ... 32 bits; where
// a vertex's coordinate is the same at both times, both at once, so that it does not start to
// move.
void shorten(const Query& q, std::vector<Query>& out) {
  for (int i = 0; i < 8; ++i)
    for (int a = 0; a < 3; ++a) {
      const double v = q.x[i][a];
      const int twin = i < 4 ? i + 4 : i - 4;
      const bool both = q.x[twin][a] == v;
      if (both && twin < i) continue;  // done with the vertex's start
      std::vector<double> shorter = {0, std::trunc(v)};
      for (int bits = 1; bits <= 32; bits *= 2)
        shorter.push_back(with_bits(v, bits, Rounding::TowardZero));
      for (const double s : shorter) {
        if (s == v) continue;
        Query c = q;
        coord(c.x[i], a) = s;
        if (both) coord(c.x[twin], a) = s;
        out.push_back(std::move(c));
      }
    }
}

bool has_negative_zero(const Query& q) {
  for (const Vec3& p : q.x)
    for (int a = 0; a < 3; ++a)
      if (p[a] == 0 && std::signbit(p[a])) return true;
  return false;
}

// q with every -0 written as 0: the same case (case_hash), one text.
Query without_negative_zeros(Query q) {
  for (Vec3& p : q.x)
    for (int a = 0; a < 3; ++a)
      if (p[a] == 0) coord(p, a) = 0;
  return q;
}

}  // namespace

int binary_length(double v) {
  if (v == 0 || !std::isfinite(v)) return 0;
  const OddMantissa m = odd_mantissa(v);
  return m.exponent >= 0 ? m.bits() + m.exponent : std::max(m.bits(), -m.exponent);
}

bool Simplicity::operator<(const Simplicity& o) const {
  return std::tie(moving, length, magnitude) < std::tie(o.moving, o.length, o.magnitude);
}

Simplicity simplicity_of(const Query& q) {
  Simplicity s;
  for (int i = 0; i < 4; ++i) s.moving += q.x[i] != q.x[i + 4];
  for (const Vec3& p : q.x)
    for (int a = 0; a < 3; ++a) {
      s.length += binary_length(p[a]);
      s.magnitude += std::fabs(p[a]);
    }
  return s;
}

std::vector<Query> simplifications(const Query& q) {
  std::vector<Query> out;
  stop_motion(q, out);
  change_frame(q, out);
  shorten(q, out);
  return out;
}

Query simplify_failure(Query q, const QueryFails& fails, int max_evaluations) {
  const Query plain = without_negative_zeros(q);
  if (has_negative_zero(q) && fails(plain)) q = plain;
  // Round robin over the candidates: after a change, go on from the kind of change that worked
  // instead of retrying every earlier one that just failed to keep the failure.
  std::size_t next = 0;
  for (bool changed = true; changed && max_evaluations > 0;) {
    changed = false;
    const std::vector<Query> all = simplifications(q);
    const Simplicity now = simplicity_of(q);
    for (std::size_t k = 0; k < all.size() && !changed && max_evaluations > 0; ++k) {
      const std::size_t j = (next + k) % all.size();
      if (!(simplicity_of(all[j]) < now)) continue;
      --max_evaluations;
      const Query c = without_negative_zeros(all[j]);
      if (fails(c)) q = c, next = j, changed = true;
    }
  }
  return q;
}

}  // namespace fdh::verify

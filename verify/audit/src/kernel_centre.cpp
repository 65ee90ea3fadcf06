#include "kernel_centre.hpp"

#include <cmath>

#include "fdh/normal_cone.hpp"

namespace fdh::audit {
namespace {

struct P2 {
  double a, b;
};

// Keeps the part of the convex polygon `poly` left of the line A -> B (Sutherland-Hodgman).
void clip(std::vector<P2>& poly, const P2& A, const P2& B, std::vector<P2>& out) {
  out.clear();
  const double ea = B.a - A.a, eb = B.b - A.b;
  const auto side = [&](const P2& p) { return ea * (p.b - A.b) - eb * (p.a - A.a); };
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p.a + t * (q.a - p.a), p.b + t * (q.b - p.b)});
    }
  }
  poly.swap(out);
}

}  // namespace

Vec3 kernel_centre(const std::vector<int>& loop, const std::vector<Vec3>& x, int bit) {
  Vec3 mean{};
  for (const int v : loop) mean += x[v];
  mean = (1.0 / double(loop.size())) * mean;
  // In-plane axes u, w with (u x w).d > 0: counter-clockwise seen from d.
  const Vec3 d = mask_direction(bit);
  const Vec3 e = std::fabs(d.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = cross(d, e);
  Vec3 w = cross(d, u);
  if (dot(cross(u, w), d) < 0) w = -w;
  thread_local std::vector<P2> pts, poly, scratch;
  pts.clear();
  double lo_a = HUGE_VAL, hi_a = -HUGE_VAL, lo_b = HUGE_VAL, hi_b = -HUGE_VAL;
  for (const int v : loop) {
    const Vec3 p = x[v] - mean;
    pts.push_back({dot(p, u), dot(p, w)});
    lo_a = std::fmin(lo_a, pts.back().a), hi_a = std::fmax(hi_a, pts.back().a);
    lo_b = std::fmin(lo_b, pts.back().b), hi_b = std::fmax(hi_b, pts.back().b);
  }
  poly = {{lo_a, lo_b}, {hi_a, lo_b}, {hi_a, hi_b}, {lo_a, hi_b}};
  for (std::size_t k = 0; k < pts.size() && !poly.empty(); ++k)
    clip(poly, pts[k], pts[(k + 1) % pts.size()], scratch);
  if (poly.empty()) return mean;
  P2 c{0, 0};
  for (const P2& p : poly) c.a += p.a, c.b += p.b;
  c.a /= double(poly.size()), c.b /= double(poly.size());
  return mean + (c.a / dot(u, u)) * u + (c.b / dot(w, w)) * w;
}

}  // namespace fdh::audit

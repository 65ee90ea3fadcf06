#include "fdh/check/contact.hpp"

#include "fdh/check/registry.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"

namespace fdh::verify {

TwinContact twin_contact(const Query& q) {
  // exact::point_triangle decides contact only; at δ > 0 the static query is a CCD one.
  if (decision_of(q) == Decision::PointTriangle && q.min_distance == 0) {
    const exact::PointTriangleContact e =
        exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
    return {e.hit, exact::to_string(e.kind), e.time, e.time};
  }
  const exact::CcdContact e = exact::ccd(q);
  return {e.hit, "", e.time_lo, e.time_hi};
}

std::string contact_words(const TwinContact& c) {
  if (!c.hit) return "no";
  const std::string kind = c.kind.empty() ? "" : c.kind + " ";
  if (c.time_exact()) return "hit (" + kind + "at t = " + c.time_lo + ")";
  return "hit (" + kind + "at t in [" + c.time_lo + ", " + c.time_hi + "])";
}

}  // namespace fdh::verify

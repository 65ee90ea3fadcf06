// `robust`: segment BB' against the closed still triangle DEF, decided by signs of orient3d
// behind a static error filter (fdh/orient3d_filter.hpp). The filter answers yes or no only
// when every sign it used is certain; otherwise the caller's exact test decides. So the
// verdict always equals the exact one. fast/ holds no exact arithmetic: the fallback is passed
// in (fdh::exact::point_triangle_hit from reference/ in this project).
#pragma once

#include "fdh/filtered.hpp"
#include "fdh/vec3.hpp"

namespace fdh {

Filtered robust_point_triangle_filter(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                      const Vec3& f);

using PointTriangleTest = bool (*)(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                   const Vec3& f);

inline bool robust_point_triangle(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e,
                                  const Vec3& f, PointTriangleTest exact_fallback) {
  return or_exact(robust_point_triangle_filter(b0, b1, d, e, f),
                  [&] { return exact_fallback(b0, b1, d, e, f); });
}

}  // namespace fdh

#include "fdh/verify/methods.hpp"

#include <stdexcept>

#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/kdop.hpp"
#include "fdh/point_triangle/linear_system.hpp"
#include "fdh/point_triangle/paper.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh::verify {
namespace {

using Test = PointTriangleTest;

std::function<bool(const Query&)> on_query(Test t) {
  return [t](const Query& q) { return t(q.b0(), q.b1(), q.d(), q.e(), q.f()); };
}

// The paper's method behind the tree's box test (§3): a hit needs overlapping k-DOPs too.
std::function<bool(const Query&)> gated(Test t, int k) {
  return [t, k](const Query& q) {
    const bool boxes = with_k(k, [&](auto kc) {
      constexpr int K = decltype(kc)::value;
      const Vec3 sweep[2] = {q.b0(), q.b1()}, tri[3] = {q.d(), q.e(), q.f()};
      return overlap(kdop_of<K>(sweep, 2), kdop_of<K>(tri, 3));
    });
    return boxes && t(q.b0(), q.b1(), q.d(), q.e(), q.f());
  };
}

// `exact` and `robust` take the static vertex-face test when the triangle stands still: the
// same verdict (a property checks it), with the contact kind and at a fraction of the cost.
bool exact_any(const Query& q) {
  return q.is_static_vf() ? exact::point_triangle_hit(q.b0(), q.b1(), q.d(), q.e(), q.f())
                          : exact::ccd_hit(q);
}

bool robust_static(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  return robust_point_triangle(b0, b1, d, e, f, &exact::point_triangle_hit);
}

bool robust_any(const Query& q) {
  return q.is_static_vf() ? robust_static(q.b0(), q.b1(), q.d(), q.e(), q.f())
                          : robust_ccd(q, &exact::ccd_hit);
}

}  // namespace

std::vector<Method> all_methods(int gate_k) {
  if (gate_k != 0 && !is_valid_k(gate_k))
    throw std::invalid_argument("--gate takes 6, 14, 18 or 26, not " + std::to_string(gate_k));
  const auto paper = [gate_k](Test t) { return gate_k ? gated(t, gate_k) : on_query(t); };
  return {
      {"exact", "CGAL/GMP exact tests (reference/): segment-triangle, CCD by Sturm sequences",
       &exact_any, true, &exact::point_triangle_hit},
      {"robust", "floating-point filters with error bounds, exact fallback", &robust_any, true,
       &robust_static},
      {"float-cubic", "Provot/Bridson: float cubic roots, then inside tests", &float_cubic, true},
      {"paper-literal", "Han & Jia 3.2 as printed", paper(&paper_literal), false, &paper_literal},
      {"paper-intended", "Han & Jia 3.2 as Figs. 3-4 read", paper(&paper_intended), false,
       &paper_intended},
      {"linear-system", "3x3 solve for (t, u, v), singular = no", on_query(&linear_system), false,
       &linear_system},
  };
}

std::vector<Method> select_methods(const std::vector<std::string>& names, int gate_k) {
  const std::vector<Method> all = all_methods(gate_k);
  std::vector<Method> out;
  for (const std::string& n : names) {
    bool found = false;
    for (const Method& m : all)
      if (m.name == n) out.push_back(m), found = true;
    if (!found) {
      std::string known;
      for (const Method& m : all) known += (known.empty() ? "" : ", ") + m.name;
      throw std::invalid_argument("unknown method '" + n + "' (known: " + known + ")");
    }
  }
  return out;
}

}  // namespace fdh::verify

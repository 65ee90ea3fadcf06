#include "fdh/verify/methods.hpp"

#include <stdexcept>

#include "fdh/exact/point_triangle.hpp"
#include "fdh/kdop.hpp"
#include "fdh/point_triangle/linear_system.hpp"
#include "fdh/point_triangle/paper.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh::verify {
namespace {

using Test = bool (*)(const Vec3&, const Vec3&, const Vec3&, const Vec3&, const Vec3&);

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

bool robust(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  return robust_point_triangle(b0, b1, d, e, f, &exact::point_triangle_hit);
}

}  // namespace

std::vector<Method> all_methods(int gate_k) {
  if (gate_k != 0 && !is_valid_k(gate_k))
    throw std::invalid_argument("--gate takes 6, 14, 18 or 26, not " + std::to_string(gate_k));
  const auto paper = [gate_k](Test t) { return gate_k ? gated(t, gate_k) : on_query(t); };
  return {
      {"exact", "CGAL/GMP exact segment-triangle test (reference/)",
       on_query(&exact::point_triangle_hit)},
      {"robust", "orient3d signs behind a static filter, exact fallback", on_query(&robust)},
      {"paper-literal", "Han & Jia 3.2 as printed", paper(&paper_literal)},
      {"paper-intended", "Han & Jia 3.2 as Figs. 3-4 read", paper(&paper_intended)},
      {"linear-system", "3x3 solve for (t, u, v), singular = no", on_query(&linear_system)},
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

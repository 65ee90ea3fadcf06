#include "fdh/check/registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "fdh/ccd/float_cubic.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/kdop.hpp"
#include "fdh/point_triangle/linear_system.hpp"
#include "fdh/point_triangle/paper.hpp"
#include "fdh/point_triangle/robust.hpp"

namespace fdh::verify {

const char* to_string(Decision d) {
  switch (d) {
    case Decision::PointTriangle:
      return "point-triangle";
    case Decision::VertexFaceCcd:
      return "vertex-face-ccd";
    case Decision::EdgeEdgeCcd:
      return "edge-edge-ccd";
    case Decision::KdopBuild:
      return "kdop-build";
    case Decision::KdopOverlap:
      return "kdop-overlap";
    case Decision::VertexFaceToi:
      return "vertex-face-toi";
    case Decision::EdgeEdgeToi:
      return "edge-edge-toi";
  }
  return "?";
}

const char* to_string(Promise p) {
  switch (p) {
    case Promise::Exact:
      return "exact";
    case Promise::Conservative:
      return "conservative";
    case Promise::None:
      return "none";
  }
  return "?";
}

const char* to_string(TimePromise p) {
  switch (p) {
    case TimePromise::Enclosure:
      return "exact-enclosure";
    case TimePromise::NeverLate:
      return "never-late";
    case TimePromise::None:
      return "none";
  }
  return "?";
}

Decision toi_decision_of(const Query& q) {
  return q.kind == QueryKind::EdgeEdge ? Decision::EdgeEdgeToi : Decision::VertexFaceToi;
}

std::size_t toi_index(Decision d) {
  return d == Decision::EdgeEdgeToi ? 1 : 0;
}

Toi twin_toi(const Query& q, double width) {
  return exact::ccd_toi(q, 0, 1, width);
}

Decision decision_of(const Query& q) {
  if (q.kind == QueryKind::EdgeEdge) return Decision::EdgeEdgeCcd;
  return q.is_static_vf() ? Decision::PointTriangle : Decision::VertexFaceCcd;
}

// At δ > 0 the static question is the vertex-face one with a still triangle (docs/methods.md,
// "Minimum separation"): exact::point_triangle_hit decides contact only, exact::ccd_hit reads δ.
bool twin_hit(const Query& q, Decision d) {
  return d == Decision::PointTriangle && q.min_distance == 0
             ? exact::point_triangle_hit(q.b0(), q.b1(), q.d(), q.e(), q.f())
             : exact::ccd_hit(q);
}

bool twin_hit(const Query& q) {
  return twin_hit(q, decision_of(q));
}

namespace {

using Test = PointTriangleTest;

QueryTest on_query(Test t) {
  return [t](const Query& q) { return t(q.b0(), q.b1(), q.d(), q.e(), q.f()); };
}

// A method without a bounding volume of its own behind the tree's box test (§3): a hit needs
// overlapping k-DOPs too.
QueryTest gated(Test t, int k) {
  return [t, k](const Query& q) {
    const bool boxes = with_k(k, [&](auto kc) {
      constexpr int K = decltype(kc)::value;
      const Vec3 sweep[2] = {q.b0(), q.b1()}, tri[3] = {q.d(), q.e(), q.f()};
      return overlap(kdop_of<K>(sweep, 2), kdop_of<K>(tri, 3));
    });
    return boxes && t(q.b0(), q.b1(), q.d(), q.e(), q.f());
  };
}

bool robust_static(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  return robust_point_triangle(b0, b1, d, e, f, &exact::point_triangle_hit);
}

bool robust_moving(const Query& q) {
  return robust_ccd(q, &exact::ccd_hit);
}

Toi robust_toi(const Query& q, double width) {
  return robust_ccd_toi(q, width, &exact::ccd_toi);
}

Toi float_cubic_time(const Query& q, double) {
  return float_cubic_toi(q);
}

// At δ > 0 robust's static path is its CCD path (robust_ccd reads δ), as the twin's is.
bool robust_static_query(const Query& q) {
  return q.min_distance == 0 ? robust_static(q.b0(), q.b1(), q.d(), q.e(), q.f())
                             : robust_moving(q);
}

Filtered robust_static_filter(const Query& q) {
  if (q.min_distance > 0) return robust_ccd_filter(q);
  return robust_point_triangle_filter(q.b0(), q.b1(), q.d(), q.e(), q.f());
}

bool twin_static_query(const Query& q) {
  return twin_hit(q, Decision::PointTriangle);
}

// A method of all three query decisions, the static one as a plain function.
Method all_kinds(std::string name, std::string summary, Promise promise, Test point_triangle,
                 QueryTest moving) {
  return {
      std::move(name), std::move(summary), promise, {on_query(point_triangle), moving, moving}, {},
      point_triangle};
}

// The methods of this project, in all_methods()'s order.
std::vector<Method> built_in_methods(int gate_k) {
  if (gate_k != 0 && !is_valid_k(gate_k))
    throw std::invalid_argument("--gate takes 6, 14, 18 or 26, not " + std::to_string(gate_k));
  const auto paper = [gate_k](Test t) { return gate_k ? gated(t, gate_k) : on_query(t); };
  Method twin = all_kinds("exact",
                          "CGAL/GMP exact tests (reference/): segment-triangle, CCD by Sturm "
                          "sequences; the exact twin of every query decision",
                          Promise::Exact, &exact::point_triangle_hit, &exact::ccd_hit);
  twin.test[std::size_t(Decision::PointTriangle)] = &twin_static_query;
  twin.is_twin = true;
  twin.answers_min_distance = true;
  twin.toi = {&twin_toi, &twin_toi};
  twin.time_promise = TimePromise::Enclosure;
  Method robust = all_kinds("robust", "floating-point filters with error bounds, exact fallback",
                            Promise::Exact, &robust_static, &robust_moving);
  robust.test[std::size_t(Decision::PointTriangle)] = &robust_static_query;
  robust.filter = {&robust_static_filter, &robust_ccd_filter, &robust_ccd_filter};
  robust.answers_min_distance = true;
  robust.toi = {&robust_toi, &robust_toi};
  robust.time_promise = TimePromise::Enclosure;
  Method float_cubic{"float-cubic",
                     "Provot/Bridson: float cubic roots, then inside tests",
                     Promise::None,
                     // A CCD method: a static query is a moving one whose triangle stays.
                     {&fdh::float_cubic, &fdh::float_cubic, &fdh::float_cubic},
                     {}};
  float_cubic.toi = {&float_cubic_time, &float_cubic_time};  // promises nothing: measured
  float_cubic.answers_min_distance = true;  // the naive float baseline at δ > 0 (t30-fast)
  return {
      twin,
      robust,
      float_cubic,
      {"paper-literal",
       "Han & Jia 3.2 as printed",
       Promise::None,
       {paper(&paper_literal)},
       {},
       &paper_literal},
      {"paper-intended",
       "Han & Jia 3.2 as Figs. 3-4 read",
       Promise::None,
       {paper(&paper_intended)},
       {},
       &paper_intended},
      {"linear-system",
       "3x3 solve for (t, u, v), singular = no",
       Promise::None,
       {on_query(&linear_system)},
       {},
       &linear_system},
  };
}

// add_methods()'s: read by every run, written only while a command line is parsed.
std::vector<Method>& added_methods() {
  static std::vector<Method> methods;
  return methods;
}
std::vector<BoxMethod>& added_boxes() {
  static std::vector<BoxMethod> boxes;
  return boxes;
}

}  // namespace

std::vector<Method> all_methods(int gate_k) {
  std::vector<Method> all = built_in_methods(gate_k);
  all.insert(all.end(), added_methods().begin(), added_methods().end());
  return all;
}

void add_methods(std::vector<Method> methods, std::vector<BoxMethod> boxes) {
  std::vector<Method> taken = all_methods();
  std::vector<BoxMethod> taken_boxes = all_box_methods();
  for (const Method& m : methods) {
    for (const Method& o : taken)
      if (o.name == m.name) throw std::invalid_argument("method name '" + m.name + "' is taken");
    taken.push_back(m);
  }
  for (const BoxMethod& b : boxes) {
    for (const BoxMethod& o : taken_boxes)
      if (o.name == b.name && o.k == b.k)
        throw std::invalid_argument("k-DOP method name '" + b.name +
                                    "' (k = " + std::to_string(b.k) + ") is taken");
    taken_boxes.push_back(b);
  }
  for (Method& m : methods) added_methods().push_back(std::move(m));
  for (BoxMethod& b : boxes) added_boxes().push_back(std::move(b));
}

void remove_added_methods() {
  added_methods().clear();
  added_boxes().clear();
}

bool registry_thread_safe() {
  return std::none_of(added_methods().begin(), added_methods().end(),
                      [](const Method& m) { return m.one_thread; }) &&
         std::none_of(added_boxes().begin(), added_boxes().end(),
                      [](const BoxMethod& b) { return b.one_thread; });
}

std::vector<Method> promised_methods(int gate_k) {
  std::vector<Method> out;
  for (Method& m : all_methods(gate_k))
    if (m.promise != Promise::None && !m.is_twin) out.push_back(std::move(m));
  return out;
}

std::vector<Method> time_promised_methods() {
  std::vector<Method> out;
  for (Method& m : toi_methods())
    if (m.time_promise != TimePromise::None && !m.is_twin) out.push_back(std::move(m));
  return out;
}

std::vector<Method> toi_methods() {
  std::vector<Method> out;
  for (Method& m : all_methods())
    if (m.toi[0] || m.toi[1]) out.push_back(std::move(m));
  return out;
}

namespace {

template <class Names>
std::string joined(const Names& names) {
  std::string all;
  for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
  return all;
}

}  // namespace

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const Method& m : all_methods()) names.push_back(m.name);
  return names;
}

std::vector<Method> select_methods(const std::vector<std::string>& names, int gate_k) {
  const std::vector<Method> all = all_methods(gate_k);
  std::vector<Method> out;
  const std::vector<std::string> known = method_names();
  for (const std::string& n : names) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const Method& m) { return m.name == n; });
    if (it == all.end())
      throw std::invalid_argument("unknown method '" + n + "' (known: " + joined(known) +
                                  "; a plug-in's methods are known once --plugin FILE names it)");
    out.push_back(*it);
  }
  return out;
}

std::vector<std::string> narrow_phase_names() {
  std::vector<std::string> n;
  for (const Method& m : all_methods())
    if (m.point_triangle) n.push_back(m.name);
  return n;
}

PointTriangleTest narrow_phase_named(const std::string& name) {
  for (const Method& m : all_methods())
    if (m.name == name && m.point_triangle) return m.point_triangle;
  throw std::invalid_argument("unknown narrow phase '" + name +
                              "' (one of: " + joined(narrow_phase_names()) + ")");
}

namespace {

template <int K>
BoxMethod fdh_box() {
  BoxMethod m;
  m.name = "fdh";
  m.summary = "fast/'s k-DOP: one outward push per diagonal slab (kdop.hpp)";
  m.k = K;
  m.directions = kdop_directions(K);
  m.builds_tree = true;
  m.build = [](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    const Kdop<K> box = kdop_of<K>(pts, n);
    std::copy(box.lo.begin(), box.lo.end(), lo);
    std::copy(box.hi.begin(), box.hi.end(), hi);
  };
  m.overlap = [](const double* la, const double* ha, const double* lb, const double* hb) {
    Kdop<K> a, b;
    std::copy(la, la + K / 2, a.lo.begin()), std::copy(ha, ha + K / 2, a.hi.begin());
    std::copy(lb, lb + K / 2, b.lo.begin()), std::copy(hb, hb + K / 2, b.hi.begin());
    return overlap(a, b);
  };
  return m;
}

}  // namespace

std::vector<Direction> kdop_directions(int k) {
  std::vector<Direction> dirs;
  for (int s = 0; s < k / 2; ++s) dirs.push_back(slab_direction(k, s));
  return dirs;
}

std::vector<BoxMethod> all_box_methods() {
  std::vector<BoxMethod> all = {fdh_box<6>(), fdh_box<14>(), fdh_box<18>(), fdh_box<26>()};
  all.insert(all.end(), added_boxes().begin(), added_boxes().end());
  return all;
}

}  // namespace fdh::verify

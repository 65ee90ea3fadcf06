// The metamorphic transforms and the check of a method under them (metamorphic.hpp).
#include "fdh/check/metamorphic.hpp"

#include <array>
#include <utility>

#include "fdh/dyadic.hpp"

namespace fdh::verify {
namespace {

using Maybe = std::optional<Query>;

double& coord(Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

// A common shift of the points [from, to) (a translation, or with from = 4 a velocity), when
// every sum is exact.
Transform shift(std::string name, Vec3 by, int from) {
  return {std::move(name), [by, from](const Query& q) -> Maybe {
            Query t = q;
            for (int i = from; i < 8; ++i)
              for (int a = 0; a < 3; ++a)
                if (!add_exactly(q.x[i][a], by[a], coord(t.x[i], a))) return std::nullopt;
            return t;
          }};
}

Transform scale(std::string name, int e) {
  return {std::move(name), [e](const Query& q) -> Maybe {
            Query t = q;
            for (int i = 0; i < 8; ++i)
              for (int a = 0; a < 3; ++a)
                if (!scale_exactly(q.x[i][a], e, coord(t.x[i], a))) return std::nullopt;
            return t;
          }};
}

// New axis a is old axis p[a].
Transform axes(std::array<int, 3> p) {
  std::string name = "axes-";
  for (const int a : p) name += char('x' + a);
  return {name, [p](const Query& q) -> Maybe {
            Query t = q;
            for (Vec3& v : t.x) v = {v[p[0]], v[p[1]], v[p[2]]};
            return t;
          }};
}

// The points at t = 0 and t = 1 reordered: new point i (of 0..3) is old point p[i], at both
// times; only for queries of `kind`.
Transform relabel(std::string name, QueryKind kind, std::array<int, 4> p) {
  return {std::move(name), [kind, p](const Query& q) -> Maybe {
            if (q.kind != kind) return std::nullopt;
            Query t = q;
            for (int i = 0; i < 4; ++i) t.x[i] = q.x[p[i]], t.x[i + 4] = q.x[p[i] + 4];
            return t;
          }};
}

std::vector<Transform> make_transforms() {
  std::vector<Transform> all;
  all.push_back({"time-reversal", [](const Query& q) -> Maybe {
                   Query t = q;
                   for (int i = 0; i < 4; ++i) std::swap(t.x[i], t.x[i + 4]);
                   return t;
                 }});
  for (const std::array<int, 3>& p :
       {std::array<int, 3>{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}})
    all.push_back(axes(p));
  all.push_back({"mirror-x", [](const Query& q) -> Maybe {
                   Query t = q;
                   for (Vec3& v : t.x) v.x = -v.x;
                   return t;
                 }});
  all.push_back(shift("translate", {1.5, -2.25, 3}, 0));
  all.push_back(shift("translate-far", {0x1p30, -0x1p31, 0x1p29}, 0));
  all.push_back(shift("velocity", {0.5, -0.25, 1}, 4));
  all.push_back(scale("scale-up", 20));
  all.push_back(scale("scale-down", -20));
  all.push_back(relabel("corners-turn", QueryKind::VertexFace, {0, 2, 3, 1}));
  all.push_back(relabel("corners-flip", QueryKind::VertexFace, {0, 1, 3, 2}));
  all.push_back(relabel("edge-a-flip", QueryKind::EdgeEdge, {1, 0, 2, 3}));
  all.push_back(relabel("edge-b-flip", QueryKind::EdgeEdge, {0, 1, 3, 2}));
  all.push_back(relabel("edges-swap", QueryKind::EdgeEdge, {2, 3, 0, 1}));
  return all;
}

}  // namespace

const std::vector<Transform>& all_transforms() {
  static const std::vector<Transform> all = make_transforms();
  return all;
}

bool verdict_of(const Method& m, const Query& q) {
  return m.is_twin ? twin_hit(q) : m.hit(q);
}

std::vector<Transformed> transforms_of(const Query& q) {
  Query bare;  // no id or file name to copy for every transform
  bare.kind = q.kind;
  bare.x = q.x;
  std::vector<Transformed> out;
  for (const Transform& t : all_transforms())
    if (std::optional<Query> moved = t.apply(bare)) out.push_back({&t, std::move(*moved)});
  return out;
}

MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved,
                                   std::optional<MetamorphicFailure>* first) {
  MetamorphicCount n;
  for (const Transformed& t : moved) {
    if (!m.applies_to(t.query)) continue;
    ++n.checked;
    const bool after = verdict_of(m, t.query);
    if (after == before) continue;
    ++n.violations;
    if (first && !*first) *first = MetamorphicFailure{t.transform->name, before, after};
  }
  return n;
}

MetamorphicCount count_metamorphic(const Method& m, const Query& q,
                                   std::optional<MetamorphicFailure>* first) {
  if (!m.applies_to(q)) return {};
  return count_metamorphic(m, verdict_of(m, q), transforms_of(q), first);
}

std::optional<MetamorphicFailure> metamorphic_failure(const Method& m, const Query& q) {
  if (!m.applies_to(q)) return std::nullopt;
  const bool before = verdict_of(m, q);
  for (const Transform& t : all_transforms()) {
    const Maybe moved = t.apply(q);
    if (moved && m.applies_to(*moved) && verdict_of(m, *moved) != before)
      return MetamorphicFailure{t.name, before, !before};
  }
  return std::nullopt;
}

std::string describe(const Method& m, const MetamorphicFailure& f) {
  const auto word = [](bool hit) { return hit ? "hit" : "no"; };
  return m.name + " says " + word(f.before) + " here and " + word(f.after) + " after " +
         f.transform;
}

}  // namespace fdh::verify

// The metamorphic transforms and the check of a method under them (metamorphic.hpp).
#include "fdh/check/metamorphic.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "fdh/check/checker.hpp"
#include "fdh/dyadic.hpp"

namespace fdh::verify {
namespace {

using Maybe = std::optional<Query>;

double& coord(Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

// A computed coordinate a transform may give: zero or normal. A subnormal one could be exact,
// but a method is not asked to handle what the query did not hold.
bool in_range(double s) {
  return s == 0 || std::isnormal(s);
}

// A common shift of the points [from, to) (a translation, or with from = 4 a velocity), when
// every sum is exact (Two-Sum's error 0, dyadic.hpp) and in range.
Transform shift(std::string name, Vec3 by, int from) {
  return {std::move(name), std::nullopt, [by, from](const Query& q) -> Maybe {
            Query t = q;
            for (int i = from; i < 8; ++i)
              for (int a = 0; a < 3; ++a) {
                double& s = coord(t.x[i], a);
                if (!add_exactly(q.x[i][a], by[a], s) || !in_range(s)) return std::nullopt;
              }
            return t;
          }};
}

// Every coordinate times 2^e, when none overflows or leaves the normal range (then it is exact).
// Distances scale with the points: δ times 2^e too, under the same condition.
Transform scale(std::string name, int e) {
  return {std::move(name), std::nullopt, [e](const Query& q) -> Maybe {
            Query t = q;
            for (int i = 0; i < 8; ++i)
              for (int a = 0; a < 3; ++a) {
                double& s = coord(t.x[i], a);
                if (!scale_exactly(q.x[i][a], e, s) || !in_range(s)) return std::nullopt;
              }
            if (!scale_exactly(q.min_distance, e, t.min_distance) || !in_range(t.min_distance))
              return std::nullopt;
            return t;
          }};
}

std::string power_name(const char* what, int e) {
  return std::string(what) + "-2^" + std::to_string(e);
}

// The ladder of scales and translations from 2^-60 to 2^60 beside scale-up, scale-down and
// translate-far (2^20, 2^-20, 2^30): a method that fails only far from the unit scale (a
// tolerance in absolute units, an overflow in a product) is met there. A translation by 2^e
// moves by (2^e, -2^(e+1), 2^(e-1)), as translate-far does.
void add_powers(std::vector<Transform>& all) {
  for (const int e : {-60, -40, 40, 60}) all.push_back(scale(power_name("scale", e), e));
  for (const int e : {-60, -40, -20, 20, 40, 60})
    all.push_back(shift(power_name("translate", e),
                        {std::ldexp(1.0, e), -std::ldexp(1.0, e + 1), std::ldexp(1.0, e - 1)}, 0));
}

// New axis a is old axis p[a].
Transform axes(std::array<int, 3> p) {
  std::string name = "axes-";
  for (const int a : p) name += char('x' + a);
  return {name, std::nullopt, [p](const Query& q) -> Maybe {
            Query t = q;
            for (Vec3& v : t.x) v = {v[p[0]], v[p[1]], v[p[2]]};
            return t;
          }};
}

// The points at t = 0 and t = 1 reordered: new point i (of 0..3) is old point p[i], at both
// times; only for queries of `kind`.
Transform relabel(std::string name, QueryKind kind, std::array<int, 4> p) {
  return {std::move(name), kind, [kind, p](const Query& q) -> Maybe {
            if (q.kind != kind) return std::nullopt;
            Query t = q;
            for (int i = 0; i < 4; ++i) t.x[i] = q.x[p[i]], t.x[i + 4] = q.x[p[i] + 4];
            return t;
          }};
}

std::vector<Transform> make_transforms() {
  std::vector<Transform> all;
  all.push_back({"time-reversal", std::nullopt, [](const Query& q) -> Maybe {
                   Query t = q;
                   for (int i = 0; i < 4; ++i) std::swap(t.x[i], t.x[i + 4]);
                   return t;
                 }});
  for (const std::array<int, 3>& p :
       {std::array<int, 3>{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}})
    all.push_back(axes(p));
  all.push_back({"mirror-x", std::nullopt, [](const Query& q) -> Maybe {
                   Query t = q;
                   for (Vec3& v : t.x) v.x = -v.x;
                   return t;
                 }});
  all.push_back(shift("translate", {1.5, -2.25, 3}, 0));
  all.push_back(shift("translate-far", {0x1p30, -0x1p31, 0x1p29}, 0));
  all.push_back(shift("velocity", {0.5, -0.25, 1}, 4));
  all.push_back(scale("scale-up", 20));
  all.push_back(scale("scale-down", -20));
  add_powers(all);
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

bool judged_under_transforms(const Method& m) {
  return m.promise != Promise::None && !m.is_twin;
}

std::vector<TransformCount> transform_counts() {
  std::vector<TransformCount> out;
  for (const Transform& t : all_transforms()) out.push_back({t.name});
  return out;
}

std::vector<Transformed> transforms_of(const Query& q, std::vector<TransformCount>* counts) {
  Query bare;  // no id or file name to copy for every transform
  bare.kind = q.kind;
  bare.x = q.x;
  bare.min_distance = q.min_distance;  // kept by every transform but the scales, which scale it
  std::vector<Transformed> out;
  const std::vector<Transform>& all = all_transforms();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!all[i].for_kind(q)) continue;
    std::optional<Query> moved = all[i].apply(bare);
    if (counts) ++(moved ? (*counts)[i].applied : (*counts)[i].skipped);
    if (moved) out.push_back({&all[i], std::move(*moved)});
  }
  return out;
}

MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved, std::optional<bool> twin,
                                   MetamorphicFirsts* first) {
  MetamorphicCount n;
  const bool judged = twin && judged_under_transforms(m);
  for (const Transformed& t : moved) {
    if (!m.applies_to(t.query)) continue;
    ++n.checked;
    const bool after = verdict_of(m, t.query);
    const auto failure = [&](bool kept) {
      return MetamorphicFailure{t.transform->name, before, after, twin, kept, t.query};
    };
    if (judged) {
      ++n.judged;
      // The twin's verdict on q is the twin's on t.query: the transform keeps the truth.
      if (!keeps_promise(m.promise, after, *twin)) {
        ++n.broken;
        if (first && !first->broken) first->broken = failure(false);
      }
    }
    if (after == before) continue;
    ++n.violations;
    if (first && !first->changed)
      first->changed = failure(!judged || keeps_promise(m.promise, after, *twin));
  }
  return n;
}

MetamorphicCount count_metamorphic(const Method& m, bool before,
                                   const std::vector<Transformed>& moved,
                                   std::optional<MetamorphicFailure>* first) {
  MetamorphicFirsts firsts;
  const MetamorphicCount n = count_metamorphic(m, before, moved, std::nullopt, &firsts);
  if (first && !*first) *first = firsts.changed;
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
    if (!moved || !m.applies_to(*moved)) continue;
    const bool after = verdict_of(m, *moved);
    if (after != before)
      return MetamorphicFailure{t.name, before, after, std::nullopt, true, *moved};
  }
  return std::nullopt;
}

std::optional<MetamorphicFailure> promise_failure(const Method& m, const Query& q, bool twin) {
  if (!judged_under_transforms(m) || !m.applies_to(q)) return std::nullopt;
  const bool before = verdict_of(m, q);
  for (const Transform& t : all_transforms()) {
    const Maybe moved = t.apply(q);
    if (!moved || !m.applies_to(*moved)) continue;
    const bool after = verdict_of(m, *moved);
    if (!keeps_promise(m.promise, after, twin))
      return MetamorphicFailure{t.name, before, after, twin, false, *moved};
  }
  return std::nullopt;
}

std::optional<MetamorphicFailure> promise_failure(const Method& m, const Query& q) {
  if (!judged_under_transforms(m) || !m.applies_to(q)) return std::nullopt;
  return promise_failure(m, q, twin_hit(q));
}

std::string describe(const Method& m, const MetamorphicFailure& f) {
  if (!f.kept && f.twin) {
    Verdicts v;
    v.said = f.after, v.twin = *f.twin, v.kept = false;
    return describe(m, v) + " on the query after " + f.transform;
  }
  const auto word = [](bool hit) { return hit ? "hit" : "no"; };
  return m.name + " says " + word(f.before) + " here and " + word(f.after) + " after " +
         f.transform;
}

// One pass over the transforms: the first broken promise, else the first verdict change.
std::optional<MetamorphicFailure> metamorphic_finding_failure(const Method& m, const Query& q) {
  if (!m.applies_to(q)) return std::nullopt;
  const bool before = verdict_of(m, q);
  const std::optional<bool> twin =
      judged_under_transforms(m) ? std::optional<bool>(twin_hit(q)) : std::nullopt;
  std::optional<MetamorphicFailure> changed;
  for (const Transform& t : all_transforms()) {
    const Maybe moved = t.apply(q);
    if (!moved || !m.applies_to(*moved)) continue;
    const bool after = verdict_of(m, *moved);
    const bool kept = !twin || keeps_promise(m.promise, after, *twin);
    if (!kept) return MetamorphicFailure{t.name, before, after, twin, false, *moved};
    if (after != before && !changed)
      changed = MetamorphicFailure{t.name, before, after, twin, true, *moved};
  }
  return changed;
}

std::string metamorphic_finding(const Method& m, const Query& q) {
  const std::optional<MetamorphicFailure> f = metamorphic_finding_failure(m, q);
  if (!f) return "";
  return f->kept ? "metamorphic" : "broken-promise";
}

}  // namespace fdh::verify

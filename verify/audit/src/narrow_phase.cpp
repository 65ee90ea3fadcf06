#include "narrow_phase.hpp"

#include <algorithm>
#include <tuple>

#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/distance.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/parallel/chunks.hpp"
#include "fdh/triangle_triangle.hpp"

namespace fdh::audit {
namespace {

inline Aabb join(const Aabb& a, const Aabb& b) {
  return {{min_of(a.lo.x, b.lo.x), min_of(a.lo.y, b.lo.y), min_of(a.lo.z, b.lo.z)},
          {max_of(a.hi.x, b.hi.x), max_of(a.hi.y, b.hi.y), max_of(a.hi.z, b.hi.z)}};
}
// Within distance d of each other, or could be: apart by more than d along no axis. Rounding
// is monotonic and d a double, so a difference that rounds above d is above d exactly.
inline bool meet(const Aabb& a, const Aabb& b, double d) {
  return !(b.lo.x - a.hi.x > d || a.lo.x - b.hi.x > d || b.lo.y - a.hi.y > d ||
           a.lo.y - b.hi.y > d || b.lo.z - a.hi.z > d || a.lo.z - b.hi.z > d);
}
inline Aabb tri_box(const std::vector<Aabb>& box, const Tri& t) {
  return join(join(box[t[0]], box[t[1]]), box[t[2]]);
}

// The four points of a query: ids into the vertex lists `a` (the first `split` of them) and `b`.
Query query_of(QueryKind kind, const std::array<int, 4>& ids, int split,
               const std::vector<Vec3>& a0, const std::vector<Vec3>& a1,
               const std::vector<Vec3>& b0, const std::vector<Vec3>& b1) {
  Query q;
  q.kind = kind;
  for (int i = 0; i < 4; ++i) {
    q.x[i] = i < split ? a0[ids[i]] : b0[ids[i]];
    q.x[i + 4] = i < split ? a1[ids[i]] : b1[ids[i]];
  }
  return q;
}

// The query's two primitives (the first `split` points and the rest) apart along an axis by
// more than d at both ends of the step, the same way round. Each coordinate difference between
// a point of one and a point of the other is linear in t, so one above d at t = 0 and at t = 1
// is above d all step: they never come within d. Exact (as meet()). This drops the pairs that
// move together, which swept boxes keep: two points of a sheet falling 28 edge lengths.
bool apart_all_step(const Query& q, int split, double d) {
  for (int axis = 0; axis < 3; ++axis) {
    bool a_above = true, b_above = true;  // at both ends
    for (int end = 0; end < 2 && (a_above || b_above); ++end) {
      const Vec3* x = q.x.data() + 4 * end;
      double alo = x[0][axis], ahi = alo, blo = x[split][axis], bhi = blo;
      for (int i = 1; i < split; ++i) alo = min_of(alo, x[i][axis]), ahi = max_of(ahi, x[i][axis]);
      for (int i = split + 1; i < 4; ++i)
        blo = min_of(blo, x[i][axis]), bhi = max_of(bhi, x[i][axis]);
      a_above = a_above && alo - bhi > d;
      b_above = b_above && blo - ahi > d;
    }
    if (a_above || b_above) return true;
  }
  return false;
}

// Triangles a (positions x) and b (positions y) apart along an axis by more than d at both ends
// of the step, the same way round (as apart_all_step): nothing of one comes within d of
// anything of the other, at the step's end either.
bool tris_apart_all_step(const Tri& a, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                         const Tri& b, const std::vector<Vec3>& y0, const std::vector<Vec3>& y1,
                         double d) {
  const auto range = [](const Tri& t, const std::vector<Vec3>& x, int axis, double& lo,
                        double& hi) {
    lo = min_of(x[t[0]][axis], x[t[1]][axis], x[t[2]][axis]);
    hi = max_of(x[t[0]][axis], x[t[1]][axis], x[t[2]][axis]);
  };
  for (int axis = 0; axis < 3; ++axis) {
    double alo0, ahi0, alo1, ahi1, blo0, bhi0, blo1, bhi1;
    range(a, x0, axis, alo0, ahi0), range(a, x1, axis, alo1, ahi1);
    range(b, y0, axis, blo0, bhi0), range(b, y1, axis, blo1, bhi1);
    if ((alo0 - bhi0 > d && alo1 - bhi1 > d) || (blo0 - ahi0 > d && blo1 - ahi1 > d)) return true;
  }
  return false;
}

// A pair of primitives for the rule on pairs near by construction: its key and whether it is
// near by the ring rule.
struct PairName {
  std::uint64_t key = 0;
  bool rings = false;
};

// Whether the near rule leaves the pair out of the proximity kinds; counted in `part` unless
// `quiet`.
bool excluded(const PairName& name, const Pass& pass, Part& part, bool quiet = false) {
  long* count = nullptr;
  if (name.rings)
    count = &part.excluded.rings;
  else if (pass.near->first_frame(name.key))
    count = &part.excluded.first_frame;
  if (count && !quiet) ++*count;
  return count != nullptr;
}

void count_step(const Query& q, ViolationKind kind, const std::array<int, 4>& ids, int tri,
                const Pass& pass, Part& part);

// A moving query within D (pass.d > 0): the contact kind if it meets, the proximity kind if it
// only comes within D (each with its certified earliest time); contact only where the near
// rule leaves it out. With pass.record, only notes the pair if within D.
void moving_within(const Query& q, ViolationKind kind, const std::array<int, 4>& ids, int tri,
                   const Pass& pass, Part& part, const PairName& name) {
  const int split = q.kind == QueryKind::VertexFace ? 1 : 2;
  Query qd = q;
  qd.min_distance = pass.d;
  if (pass.record) {
    if (!name.rings && !apart_all_step(qd, split, pass.d) && robust_ccd(qd, exact::ccd_hit))
      part.recorded.push_back(name.key);
    return;
  }
  if (apart_all_step(qd, split, pass.d)) return;
  if (excluded(name, pass, part)) {
    if (apart_all_step(q, split, 0)) return;
    ++part.step.candidates;
    if (robust_ccd(q, exact::ccd_hit)) count_step(q, kind, ids, tri, pass, part);
    return;
  }
  ++part.step.candidates;
  if (!robust_ccd(qd, exact::ccd_hit)) return;
  if (robust_ccd(q, exact::ccd_hit))
    count_step(q, kind, ids, tri, pass, part);
  else
    count_step(qd, proximity_kind(kind), ids, tri, pass, part);
}

// One moving query: robust CCD, and for a contact its certified time of impact.
void moving(const Query& q, ViolationKind kind, const std::array<int, 4>& ids, int tri,
            const Pass& pass, Part& part, const PairName& name) {
  if (pass.d > 0) return moving_within(q, kind, ids, tri, pass, part, name);
  if (apart_all_step(q, q.kind == QueryKind::VertexFace ? 1 : 2, 0)) return;
  ++part.step.candidates;
  if (!robust_ccd(q, exact::ccd_hit)) return;
  count_step(q, kind, ids, tri, pass, part);
}

// A contact (q at δ = 0) or a pair within D (q at δ = D) found during the step: counted, and
// kept with its certified earliest time.
void count_step(const Query& q, ViolationKind kind, const std::array<int, 4>& ids, int tri,
                const Pass& pass, Part& part) {
  ++(part.step.*counter_of(kind));
  Violation v;
  v.kind = kind;
  v.frame = pass.frame - 1;
  v.vertices = ids;
  v.triangle = tri;
  v.query = q;
  v.toi = robust_ccd_toi(q, pass.toi_width, exact::ccd_toi);
  part.add(v, pass.keep);
}

// Closed triangles a and b within distance d (> 0), exactly: the 6 vertex-triangle and 9
// edge-edge pairs as queries that do not move, at δ = d, through robust's filter (any certain
// yes: within; all certain no: not), the rest by the exact squared distance against d^2
// (fdh/exact/distance.hpp). The caller has found that they do not meet.
bool within(const Triangle3& a, const Triangle3& b, double d) {
  bool unsure = false;
  const auto ask = [&](QueryKind kind, const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    Query x;
    x.kind = kind, x.min_distance = d;
    x.x = {p, q, r, s, p, q, r, s};
    if (apart_all_step(x, kind == QueryKind::VertexFace ? 1 : 2, d)) return false;
    const Filtered f = robust_ccd_filter(x);
    unsure = unsure || f == Filtered::Uncertain;
    return f == Filtered::Yes;
  };
  for (int i = 0; i < 3; ++i) {
    if (ask(QueryKind::VertexFace, a[i], b[0], b[1], b[2]) ||
        ask(QueryKind::VertexFace, b[i], a[0], a[1], a[2]))
      return true;
    for (int j = 0; j < 3; ++j)
      if (ask(QueryKind::EdgeEdge, a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
  }
  return unsure && exact::triangles_within(a, b, d);
}

bool boxes_apart(const Triangle3& a, const Triangle3& b, double d) {
  const auto box = [](const Triangle3& t) {
    return Aabb{{min_of(t[0].x, t[1].x, t[2].x), min_of(t[0].y, t[1].y, t[2].y),
                 min_of(t[0].z, t[1].z, t[2].z)},
                {max_of(t[0].x, t[1].x, t[2].x), max_of(t[0].y, t[1].y, t[2].y),
                 max_of(t[0].z, t[1].z, t[2].z)}};
  };
  return !meet(box(a), box(b), d);
}

// A frame violation kept: the two triangles, and as its query the edge e (0-2: of a, 3-5: of
// b) through the other triangle, or for proximity (e < 0) a's first corner against b at δ = D.
void keep_frame(const Triangle3& a, const Triangle3& b, int e, ViolationKind kind, int ta, int tb,
                const Pass& pass, Part& part) {
  Violation v;
  v.kind = kind;
  v.frame = pass.frame;
  v.vertices = {-1, -1, -1, -1};
  v.triangles = {ta, tb};
  v.query.kind = QueryKind::VertexFace;
  if (e < 0) {
    v.query.x = {a[0], b[0], b[1], b[2], a[0], b[0], b[1], b[2]};
    v.query.min_distance = pass.d;
  } else {
    const Triangle3 &s = e < 3 ? a : b, &t = e < 3 ? b : a;
    v.query.x = {s[e % 3], t[0], t[1], t[2], s[(e + 1) % 3], t[0], t[1], t[2]};
  }
  part.add(v, pass.keep);
}

// Triangles a and b that do not meet, within D (pass.d > 0)? A proximity violation unless the
// near rule leaves the pair out; with pass.record only noted. The frame's nearest pair is chosen
// among those looked at.
void frame_within(const Triangle3& a, const Triangle3& b, ViolationKind kind, int ta, int tb,
                  const Pass& pass, Part& part, const PairName& name) {
  if (boxes_apart(a, b, pass.d)) return;
  if (pass.record) {
    if (name.rings) return;
    if (within(a, b, pass.d)) return part.recorded.push_back(name.key);
  } else if (excluded(name, pass, part)) {
    return;
  }
  NearestCandidate& n = part.nearest[kind != ViolationKind::SelfIntersection];
  n = std::min(n, NearestCandidate{distance_estimate(a, b), int(proximity_kind(kind)), ta, tb});
  if (pass.record || !within(a, b, pass.d)) return;
  ++(kind == ViolationKind::SelfIntersection ? part.self_proximity : part.obstacle_proximity);
  keep_frame(a, b, -1, proximity_kind(kind), ta, tb, pass, part);
}

// Triangles a (of the cloth) and b at the frame, by the robust triangle-triangle test; within
// D as well with pass.d > 0.
void frame_pair(const Triangle3& a, const Triangle3& b, ViolationKind kind, int ta, int tb,
                const Pass& pass, Part& part, long& count, const PairName& name) {
  ++part.static_candidates;
  const int e = robust_triangle_triangle_edge(a, b, exact::point_triangle_hit);
  if (e < 0) {
    if (pass.d > 0) frame_within(a, b, kind, ta, tb, pass, part, name);
    return;
  }
  if (pass.d > 0 && pass.record && !name.rings) part.recorded.push_back(name.key);
  if (pass.d > 0 && !pass.record && !excluded(name, pass, part, true)) {
    NearestCandidate& n = part.nearest[kind != ViolationKind::SelfIntersection];
    n = std::min(n, NearestCandidate{0, int(proximity_kind(kind)), ta, tb});
  }
  ++count;
  keep_frame(a, b, e, kind, ta, tb, pass, part);
}

Triangle3 corners(const std::vector<Vec3>& x, const Tri& t) {
  return {x[t[0]], x[t[1]], x[t[2]]};
}

// Vertices [v, v_end) of mesh A against triangle `tri` of mesh B: split 1 in query_of.
template <class Ids>
void vertices_against(const int* v, const int* v_end, const std::vector<Aabb>& abox,
                      const std::vector<Vec3>& a0, const std::vector<Vec3>& a1, const Tri& t,
                      int tri, const Aabb& tbox, const std::vector<Vec3>& b0,
                      const std::vector<Vec3>& b1, ViolationKind kind, const Pass& pass, Part& part,
                      Ids same) {
  for (; v != v_end; ++v) {
    if (same(*v, t) || !meet(abox[*v], tbox, pass.d)) continue;
    const std::array<int, 4> ids{*v, t[0], t[1], t[2]};
    PairName name;
    if (pass.d > 0)
      name = {NearPairs::key(int(kind), *v, tri),
              kind == ViolationKind::SelfVertexFace && pass.near->rings_near(v, 1, t.data(), 3)};
    moving(query_of(QueryKind::VertexFace, ids, 1, a0, a1, b0, b1), kind, ids, tri, pass, part,
           name);
  }
}

}  // namespace

void vertex_boxes(Pass& pass) {
  const auto fill = [](const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                       std::vector<Aabb>& box) {
    box.resize(x0.size());
    parallel::for_chunks(x0.size(), 8192, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const Vec3 &p = x0[i], &q = x1[i];
        box[i] = {{min_of(p.x, q.x), min_of(p.y, q.y), min_of(p.z, q.z)},
                  {max_of(p.x, q.x), max_of(p.y, q.y), max_of(p.z, q.z)}};
      }
    });
  };
  fill(*pass.c0, *pass.c1, pass.cbox);
  fill(*pass.o0, *pass.o1, pass.obox);
}

bool earlier(const Violation& a, const Violation& b) {
  const bool sa = is_step(a.kind), sb = is_step(b.kind);
  if (sa != sb) return sa;
  if (sa)
    return std::tie(a.toi.t_lo, a.toi.t_hi, a.kind, a.vertices) <
           std::tie(b.toi.t_lo, b.toi.t_hi, b.kind, b.vertices);
  return std::tie(a.kind, a.triangles) < std::tie(b.kind, b.triangles);
}

void Part::add(Violation v, int keep) {
  if (keep <= 0) return;
  kept.push_back(v);
  if (kept.size() < 2 * std::size_t(keep)) return;
  std::nth_element(kept.begin(), kept.begin() + keep, kept.end(), earlier);
  kept.resize(keep);
}

void Part::merge(Part& other, int keep) {
  step.add(other.step);
  self_intersections += other.self_intersections;
  obstacle_intersections += other.obstacle_intersections;
  static_candidates += other.static_candidates;
  self_proximity += other.self_proximity, obstacle_proximity += other.obstacle_proximity;
  excluded.add(other.excluded);
  recorded.insert(recorded.end(), other.recorded.begin(), other.recorded.end());
  for (int i = 0; i < 2; ++i) nearest[i] = std::min(nearest[i], other.nearest[i]);
  for (Violation& v : other.kept) add(v, keep);
}

void self_pair(const MeshParts& cloth, int a, int b, const Pass& pass, Part& part) {
  const Tri &ta = cloth.tris[a], &tb = cloth.tris[b];
  const auto& x0 = *pass.c0;
  const auto& x1 = *pass.c1;
  if (pass.ccd) {
    const Aabb ba = tri_box(pass.cbox, ta), bb = tri_box(pass.cbox, tb);
    // Nothing of a meets anything of b, the frame's pair included.
    if (!meet(ba, bb, pass.d) || tris_apart_all_step(ta, x0, x1, tb, x0, x1, pass.d)) return;
    const auto in = [](int v, const Tri& t) { return v == t[0] || v == t[1] || v == t[2]; };
    constexpr auto kVF = ViolationKind::SelfVertexFace;
    vertices_against(cloth.vertices_begin(a), cloth.vertices_end(a), pass.cbox, x0, x1, tb, b, bb,
                     x0, x1, kVF, pass, part, in);
    vertices_against(cloth.vertices_begin(b), cloth.vertices_end(b), pass.cbox, x0, x1, ta, a, ba,
                     x0, x1, kVF, pass, part, in);
    for (const int* e = cloth.edges_begin(a); e != cloth.edges_end(a); ++e) {
      const Edge& ea = cloth.edges[*e];
      const Aabb eab = join(pass.cbox[ea[0]], pass.cbox[ea[1]]);
      for (const int* g = cloth.edges_begin(b); g != cloth.edges_end(b); ++g) {
        const Edge& eb = cloth.edges[*g];
        if (ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1]) continue;
        if (!meet(eab, join(pass.cbox[eb[0]], pass.cbox[eb[1]]), pass.d)) continue;
        const std::array<int, 4> ids{ea[0], ea[1], eb[0], eb[1]};
        PairName name;
        if (pass.d > 0)
          name = {
              NearPairs::key(int(ViolationKind::SelfEdgeEdge), std::min(*e, *g), std::max(*e, *g)),
              pass.near->rings_near(ea.data(), 2, eb.data(), 2)};
        moving(query_of(QueryKind::EdgeEdge, ids, 4, x0, x1, x0, x1), ViolationKind::SelfEdgeEdge,
               ids, -1, pass, part, name);
      }
    }
  }
  if (shares_vertex(ta, tb)) return;
  const int lo = std::min(a, b), hi = std::max(a, b);  // the pair named the same either way
  PairName name;
  if (pass.d > 0)
    name = {NearPairs::key(int(ViolationKind::SelfIntersection), lo, hi),
            pass.near->rings_near(ta.data(), 3, tb.data(), 3)};
  frame_pair(corners(x1, cloth.tris[lo]), corners(x1, cloth.tris[hi]),
             ViolationKind::SelfIntersection, lo, hi, pass, part, part.self_intersections, name);
}

void obstacle_pair(const MeshParts& cloth, const MeshParts& obstacle, int c, int o,
                   const Pass& pass, Part& part) {
  const Tri &tc = cloth.tris[c], &to = obstacle.tris[o];
  if (pass.ccd) {
    const Aabb bc = tri_box(pass.cbox, tc), bo = tri_box(pass.obox, to);
    if (!meet(bc, bo, pass.d) ||
        tris_apart_all_step(tc, *pass.c0, *pass.c1, to, *pass.o0, *pass.o1, pass.d))
      return;
    const auto never = [](int, const Tri&) { return false; };  // two meshes share no vertex
    vertices_against(cloth.vertices_begin(c), cloth.vertices_end(c), pass.cbox, *pass.c0, *pass.c1,
                     to, o, bo, *pass.o0, *pass.o1, ViolationKind::ClothVertexObstacle, pass, part,
                     never);
    vertices_against(obstacle.vertices_begin(o), obstacle.vertices_end(o), pass.obox, *pass.o0,
                     *pass.o1, tc, c, bc, *pass.c0, *pass.c1, ViolationKind::ObstacleVertexCloth,
                     pass, part, never);
    for (const int* e = cloth.edges_begin(c); e != cloth.edges_end(c); ++e) {
      const Edge& ea = cloth.edges[*e];
      const Aabb eab = join(pass.cbox[ea[0]], pass.cbox[ea[1]]);
      for (const int* g = obstacle.edges_begin(o); g != obstacle.edges_end(o); ++g) {
        const Edge& eb = obstacle.edges[*g];
        if (!meet(eab, join(pass.obox[eb[0]], pass.obox[eb[1]]), pass.d)) continue;
        const std::array<int, 4> ids{ea[0], ea[1], eb[0], eb[1]};
        const PairName name{NearPairs::key(int(ViolationKind::ClothEdgeObstacleEdge), *e, *g)};
        moving(query_of(QueryKind::EdgeEdge, ids, 2, *pass.c0, *pass.c1, *pass.o0, *pass.o1),
               ViolationKind::ClothEdgeObstacleEdge, ids, -1, pass, part, name);
      }
    }
  }
  const PairName name{NearPairs::key(int(ViolationKind::ObstacleIntersection), c, o)};
  frame_pair(corners(*pass.c1, tc), corners(*pass.o1, to), ViolationKind::ObstacleIntersection, c,
             o, pass, part, part.obstacle_intersections, name);
}

}  // namespace fdh::audit

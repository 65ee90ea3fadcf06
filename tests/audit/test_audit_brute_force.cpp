// The engine against a brute-force audit (every pair, exact twins only) on small random cloths
// and obstacles, flat and crumpled, still and moving: the broad phase and the normal-cone
// culling lose nothing and add nothing. And the same reports for 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "audit_meshes.hpp"
#include "fdh/audit/auditor.hpp"

namespace fdh::audit {
namespace {

using testing::grid;
using testing::Mesh;

// A violation named the same whatever the order the engine met its primitives in.
using Key = std::tuple<int, std::array<int, 4>, int>;
Key key_of(const Violation& v) {
  std::array<int, 4> ids = v.vertices;
  if (v.kind == ViolationKind::SelfEdgeEdge) {
    std::array<int, 2> a{std::min(ids[0], ids[1]), std::max(ids[0], ids[1])},
        b{std::min(ids[2], ids[3]), std::max(ids[2], ids[3])};
    if (b < a) std::swap(a, b);
    ids = {a[0], a[1], b[0], b[1]};
  } else if (v.kind == ViolationKind::ClothEdgeObstacleEdge) {
    ids = {std::min(ids[0], ids[1]), std::max(ids[0], ids[1]), std::min(ids[2], ids[3]),
           std::max(ids[2], ids[3])};
  } else if (!is_step(v.kind)) {
    ids = {v.triangles[0], v.triangles[1], -1, -1};
    if (v.kind == ViolationKind::SelfIntersection && ids[1] < ids[0]) std::swap(ids[0], ids[1]);
  }
  return {int(v.kind), ids, v.triangle};
}

std::multiset<Key> keys(const std::vector<Violation>& vs) {
  std::multiset<Key> k;
  for (const Violation& v : vs) k.insert(key_of(v));
  return k;
}

// A random sequence: a 6 x 6 cloth (flat at z = 0 exactly, or crumpled), a 3 x 3 obstacle
// (still or moving), three frames of random motion, from small to many edge lengths.
struct Sequence {
  Topology topology;
  std::vector<std::vector<Vec3>> cloth, obstacle;
};

Sequence random_sequence(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const Mesh c = grid(6, 1.0, {0, 0, 0});
  const Mesh o = grid(3, 1.5, {u(rng) + 1, u(rng) + 1, -0.5});
  Sequence s;
  s.topology.cloth_vertices = int(c.x.size());
  s.topology.cloth = c.tris;
  s.topology.obstacle_vertices = int(o.x.size());
  s.topology.obstacle = o.tris;
  const bool flat = seed % 3 == 0, still = seed % 2 == 0;
  const double bump = flat ? 0 : 0.2 + seed % 4 * 0.4, motion = (seed / 3) % 3 * 0.8;
  std::vector<Vec3> x = c.x, y = o.x;
  for (Vec3& p : x) p.z = bump * u(rng);
  for (int f = 0; f < 3; ++f) {
    s.cloth.push_back(x);
    s.obstacle.push_back(y);
    const double drop = std::floor(4 * u(rng));  // a whole flat sheet moves and stays flat
    for (Vec3& p : x) {
      p.z += drop;
      if (!flat || rng() % 6 == 0) p = p + motion * Vec3{u(rng), u(rng), u(rng)};
    }
    if (!still)
      for (Vec3& p : y) p = p + Vec3{0, 0, 0.6 * u(rng)} + 0.3 * Vec3{u(rng), u(rng), u(rng)};
  }
  return s;
}

TEST(AuditBruteForce, ViolationsEqualAllPairs) {
  long total = 0;
  const int ks[] = {6, 14, 18, 26};
  for (unsigned seed = 0; seed < 36; ++seed) {
    const Sequence s = random_sequence(seed);
    Options o;
    o.k = ks[seed % 4];
    o.keep = 1 << 20;
    Auditor audit(s.topology, o);
    for (int f = 0; f < 3; ++f) {
      const FrameReport r = audit.add_frame(s.cloth[f], s.obstacle[f]);
      const auto& x0 = s.cloth[f > 0 ? f - 1 : 0];
      const auto& y0 = s.obstacle[f > 0 ? f - 1 : 0];
      const auto expected =
          testing::brute_force(s.topology, x0, s.cloth[f], y0, s.obstacle[f], f, f > 0);
      ASSERT_EQ(keys(r.violations), keys(expected)) << "seed " << seed << " frame " << f;
      EXPECT_EQ(long(r.violations.size()),
                r.step.total() + r.self_intersections + r.obstacle_intersections);
      total += long(expected.size());
    }
  }
  EXPECT_GT(total, 100);  // the sequences do collide: the comparison is not of empty sets
}

// A 9 x 9 sheet folded into a meander (sine-generated, the tangent turning up to `amplitude`
// each way, overhanging beyond pi / 2), three frames apart in phase and position, some vertices
// jittered: culling works on its many small flat patches, and the jitter makes contacts.
Sequence folded_sequence(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 9;
  const Mesh c = grid(n, 1.0, {0, 0, 0});
  Sequence s;
  s.topology.cloth_vertices = int(c.x.size());
  s.topology.cloth = c.tris;
  const double amplitude = 1.2 + 0.3 * u(rng), pi = std::acos(-1.0);
  for (int f = 0; f < 3; ++f) {
    const double phase = 0.1 * f * u(rng);
    std::vector<double> cx(n), cz(n);
    for (int i = 1; i < n; ++i) {
      const double theta = amplitude * std::sin(2 * pi * ((i - 0.5) / 4.0 + phase));
      cx[i] = cx[i - 1] + std::cos(theta);
      cz[i] = cz[i - 1] + std::sin(theta);
    }
    std::vector<Vec3> x(c.x.size());
    const Vec3 shift = Vec3{u(rng), u(rng), 3 * u(rng)};
    for (int r = 0; r < n; ++r)
      for (int i = 0; i < n; ++i) x[r * n + i] = Vec3{cx[i], double(r), cz[i]} + shift;
    for (Vec3& p : x)
      if (rng() % 10 == 0) p = p + 1.5 * Vec3{u(rng), u(rng), u(rng)};
    s.cloth.push_back(x);
    s.obstacle.push_back({});
  }
  return s;
}

TEST(AuditBruteForce, ViolationsEqualAllPairsOnFoldedSheets) {
  long total = 0;
  for (unsigned seed = 0; seed < 8; ++seed) {
    const Sequence s = folded_sequence(seed);
    Options o;
    o.keep = 1 << 20;
    Auditor audit(s.topology, o);
    for (int f = 0; f < 3; ++f) {
      const FrameReport r = audit.add_frame(s.cloth[f], s.obstacle[f]);
      const auto& x0 = s.cloth[f > 0 ? f - 1 : 0];
      const auto expected = testing::brute_force(s.topology, x0, s.cloth[f], {}, {}, f, f > 0);
      ASSERT_EQ(keys(r.violations), keys(expected)) << "seed " << seed << " frame " << f;
      total += long(expected.size());
    }
  }
  EXPECT_GT(total, 20);
}

// A strip wound 1.25 times around a helix, its layers 0.5 apart: every normal leans the same
// way, yet the projection along it overlaps itself, so only the contour test keeps the whole
// strip from being called flat. Between the frames its top end sinks through the layer below.
TEST(AuditBruteForce, ViolationsEqualAllPairsOnAHelix) {
  const int around = 40, across = 3;
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int r = 0; r < across; ++r)
    for (int i = 0; i < around; ++i) {
      const double phi = 2.5 * pi * i / (around - 1), radius = 2 + 0.5 * r;
      m.x.push_back({radius * std::cos(phi), radius * std::sin(phi), 0.5 * phi / (2 * pi)});
    }
  for (int r = 0; r + 1 < across; ++r)
    for (int i = 0; i + 1 < around; ++i) {
      const int a = r * around + i, b = a + 1, d = a + around, e = d + 1;
      m.tris.push_back({a, b, e});
      m.tris.push_back({a, e, d});
    }
  Topology t;
  t.cloth_vertices = int(m.x.size());
  t.cloth = m.tris;
  std::vector<Vec3> x1 = m.x;
  for (int r = 0; r < across; ++r)
    for (int i = around - 4; i < around; ++i) x1[r * around + i].z -= 1.0;
  Options o;
  o.keep = 1 << 20;
  Auditor audit(t, o);
  const FrameReport r0 = audit.add_frame(m.x, {});
  EXPECT_EQ(r0.self_intersections, 0);
  const FrameReport r1 = audit.add_frame(x1, {});
  const auto expected = testing::brute_force(t, m.x, x1, {}, {}, 1, true);
  EXPECT_GT(expected.size(), 0u);
  EXPECT_EQ(keys(r1.violations), keys(expected));
}

TEST(AuditBruteForce, SameReportsOnOneAndTwoThreads) {
  const Mesh c = grid(60, 1.0, {0, 0, 0});
  Topology t;
  t.cloth_vertices = int(c.x.size());
  t.cloth = c.tris;
  std::vector<FrameReport> reports[2];
  for (const int threads : {1, 2}) {
    Options o;
    o.threads = threads;
    o.keep = 50;
    Auditor audit(t, o);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Vec3> x = c.x;
    for (Vec3& p : x) p.z = 0.5 * std::sin(p.x * 0.3) + 0.05 * u(rng);
    for (int f = 0; f < 3; ++f) {
      reports[threads - 1].push_back(audit.add_frame(x, {}));
      for (Vec3& p : x) p = p + 0.7 * Vec3{u(rng), u(rng), u(rng)};
    }
  }
  for (int f = 0; f < 3; ++f) {
    const FrameReport &a = reports[0][f], &b = reports[1][f];
    EXPECT_EQ(a.step.candidates, b.step.candidates);
    EXPECT_EQ(a.step.total(), b.step.total());
    EXPECT_EQ(a.static_candidates, b.static_candidates);
    EXPECT_EQ(a.self_intersections, b.self_intersections);
    ASSERT_EQ(a.violations.size(), b.violations.size());
    for (std::size_t i = 0; i < a.violations.size(); ++i) {
      EXPECT_EQ(a.violations[i].vertices, b.violations[i].vertices);
      EXPECT_EQ(a.violations[i].triangles, b.violations[i].triangles);
      EXPECT_EQ(a.violations[i].toi.t_lo, b.violations[i].toi.t_lo);
    }
  }
  EXPECT_GT(reports[0][2].step.total(), 0);  // it did collide
}

}  // namespace
}  // namespace fdh::audit

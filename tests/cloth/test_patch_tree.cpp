// The self-collision pass's patch tree (fdh/cloth/patch_tree.hpp): every primitive has one
// owning cell; a level cloth is flat at the root and a folded one is not; and a patch the tree
// calls flat has no contact inside it, by brute-force exact CCD over random steps.
#include "fdh/cloth/patch_tree.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fdh/exact/ccd.hpp"

namespace fdh::cloth {
namespace {

Cloth small_cloth(int grid) {
  ClothSpec spec;
  spec.grid = grid;
  spec.size = 1;
  spec.centre = {0, 0, 0};
  return Cloth(spec);
}

TEST(PatchTree, EveryPrimitiveHasOneOwnerHoldingItsParticles) {
  const Cloth c = small_cloth(6);
  const PatchTree t(c);
  std::vector<int> particle(c.n(), 0), edge(c.edges().size(), 0);
  for (const auto& n : t.nodes()) {
    if (!n.leaf()) continue;
    const int cell = t.cell_of(n), a = n.r0 * c.grid() + n.c0;
    const std::vector<int> corners = {a, a + 1, a + c.grid(), a + c.grid() + 1};
    const auto held = [&](int p) { return std::count(corners.begin(), corners.end(), p) == 1; };
    for (const int* p = t.vertices_begin(cell); p != t.vertices_end(cell); ++p) {
      ++particle[*p];
      EXPECT_TRUE(held(*p));
    }
    for (const int* e = t.edges_begin(cell); e != t.edges_end(cell); ++e) {
      ++edge[*e];
      EXPECT_TRUE(held(c.edges()[*e][0]) && held(c.edges()[*e][1]));
    }
    for (const int f : PatchTree::triangles(cell))
      for (const int p : c.triangles()[f]) EXPECT_TRUE(held(p));
  }
  EXPECT_EQ(std::count(particle.begin(), particle.end(), 1), c.n());
  EXPECT_EQ(std::count(edge.begin(), edge.end(), 1), long(edge.size()));
}

TEST(PatchTree, ALevelFallIsFlatAtTheRootAndAFoldIsNot) {
  const Cloth c = small_cloth(9);
  PatchTree t(c);
  std::vector<Vec3> x1 = c.x();
  for (Vec3& p : x1) p.y -= 0.3;
  t.update_normals(c.x(), x1);
  EXPECT_TRUE(t.flat(0, c.x(), x1));
  // Fold the far half over the near half (rows past the middle mirrored above it).
  std::vector<Vec3> folded = c.x();
  for (int r = 5; r < 9; ++r)
    for (int col = 0; col < 9; ++col) {
      Vec3& p = folded[r * 9 + col];
      const double z_mid = c.x()[4 * 9].z;
      p = {p.x, 0.05 * (r - 4), 2 * z_mid - p.z};
    }
  t.update_normals(folded, folded);
  EXPECT_FALSE(t.flat(0, folded, folded));
}

// Primitives owned by the cells under `node`.
void owned(const PatchTree& t, int node, std::vector<int>& cells) {
  const auto& n = t.nodes()[node];
  if (n.leaf()) {
    cells.push_back(t.cell_of(n));
    return;
  }
  owned(t, n.left, cells);
  owned(t, n.right, cells);
}

// Does any vertex-face or edge-edge pair owned under `node`, sharing no particle, touch during
// the step? (Brute force, exact CCD.)
bool any_contact(const Cloth& c, const PatchTree& t, int node, const std::vector<Vec3>& x0,
                 const std::vector<Vec3>& x1) {
  std::vector<int> cells;
  owned(t, node, cells);
  std::vector<int> verts, tris, edges;
  for (const int cell : cells) {
    verts.insert(verts.end(), t.vertices_begin(cell), t.vertices_end(cell));
    edges.insert(edges.end(), t.edges_begin(cell), t.edges_end(cell));
    for (const int f : PatchTree::triangles(cell)) tris.push_back(f);
  }
  const auto hit = [&](QueryKind kind, std::array<int, 4> ids) {
    Query q;
    q.kind = kind;
    for (int i = 0; i < 4; ++i) q.x[i] = x0[ids[i]], q.x[i + 4] = x1[ids[i]];
    return exact::ccd_hit(q);
  };
  for (const int p : verts)
    for (const int f : tris) {
      const Tri& tri = c.triangles()[f];
      if (p != tri[0] && p != tri[1] && p != tri[2] &&
          hit(QueryKind::VertexFace, {p, tri[0], tri[1], tri[2]}))
        return true;
    }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto& a = c.edges()[edges[i]];
      const auto& b = c.edges()[edges[j]];
      if (a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1] &&
          hit(QueryKind::EdgeEdge, {a[0], a[1], b[0], b[1]}))
        return true;
    }
  return false;
}

TEST(PatchTree, AFlatPatchHasNoContactInsideIt) {
  const Cloth c = small_cloth(5);
  PatchTree t(c);
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> u(-1, 1);
  int flat = 0, contacts = 0;
  for (int trial = 0; trial < 120; ++trial) {
    // Crumple the cloth by a random amount, then move every particle by a random step: small
    // amounts keep patches flat, large ones make the cloth cross itself.
    const double crumple = 0.3 * std::abs(u(rng)), move = 0.5 * std::abs(u(rng));
    std::vector<Vec3> x0 = c.x(), x1(c.n());
    for (Vec3& p : x0) p += crumple * Vec3{u(rng), u(rng), u(rng)};
    for (int i = 0; i < c.n(); ++i) x1[i] = x0[i] + move * Vec3{u(rng), u(rng), u(rng)};
    t.update_normals(x0, x1);
    contacts += any_contact(c, t, 0, x0, x1);
    for (int node = 0; node < int(t.nodes().size()); ++node) {
      if (!t.flat(node, x0, x1)) continue;
      ++flat;
      EXPECT_FALSE(any_contact(c, t, node, x0, x1)) << "trial " << trial << ", node " << node;
    }
  }
  // Not vacuous: both answers occur.
  EXPECT_GT(flat, 60);
  EXPECT_GT(contacts, 10);
}

}  // namespace
}  // namespace fdh::cloth

// Property 3: tree traversal ⊇ brute force. Every pair of primitives whose exact FDHs overlap
// is reported, for every k, leaf size, early-out slab, and after a refit.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <set>

#include "fdh/bvh.hpp"
#include "fdh/exact/kdop.hpp"
#include "fdh/gen/rapidcheck.hpp"

namespace fdh {
namespace {

using verify::gen_soup;
using verify::Soup;

using verify::primitive_corners;

template <int K>
void check_superset(const Soup& a, const Soup& b, int leaf_size, int first_slab) {
  Bvh<K> ta(a.tris, a.x0, a.x1, leaf_size);  // swept, like the cloth
  Bvh<K> tb(b.tris, b.x0, {}, leaf_size);    // static, like an obstacle
  std::vector<std::pair<int, int>> found;
  traverse(ta, tb, found, first_slab);
  const std::set<std::pair<int, int>> got(found.begin(), found.end());
  RC_ASSERT(got.size() == found.size());  // no pair twice
  for (const auto& pair : exact::overlapping_pairs(K, primitive_corners(a.tris, a.x0, a.x1),
                                                   primitive_corners(b.tris, b.x0, {})))
    RC_ASSERT(got.count(pair) == 1);
}

template <int K>
void check_all_options(const Soup& a, const Soup& b) {
  const int leaf_size = *rc::gen::element(1, 4);
  const int first_slab = *rc::gen::inRange(-1, Kdop<K>::kSlabs);
  check_superset<K>(a, b, leaf_size, first_slab);
}

TEST(BvhProperties, TraversalContainsBruteForce) {
  EXPECT_TRUE(rc::check("traversal-contains-brute-force", [] {
    const Soup a = *gen_soup(24), b = *gen_soup(24);
    check_all_options<6>(a, b);
    check_all_options<14>(a, b);
    check_all_options<18>(a, b);
    check_all_options<26>(a, b);
  }));
}

TEST(BvhProperties, RefitEqualsRebuild) {
  EXPECT_TRUE(rc::check("refit-equals-rebuild", [] {
    const Soup a = *gen_soup(24), moved = *gen_soup(24);
    if (moved.x0.size() < a.x0.size()) return;
    const std::vector<Vec3> y0(moved.x0.begin(), moved.x0.begin() + a.x0.size()),
        y1(moved.x1.begin(), moved.x1.begin() + a.x0.size());
    Bvh<18> t(a.tris, a.x0, a.x1);
    t.refit(y0, y1);
    // Every leaf's box contains the exact FDH of its primitives' swept corners, now.
    const auto swept = primitive_corners(t.tris(), y0, y1);
    for (const auto& n : t.nodes()) {
      if (!n.leaf()) continue;
      std::vector<Vec3> pts;
      for (int p = n.first; p < n.first + n.count; ++p)
        pts.insert(pts.end(), swept[t.prims()[p]].begin(), swept[t.prims()[p]].end());
      RC_ASSERT(exact::first_uncontained_slab(18, pts.data(), pts.size(), n.box.lo.data(),
                                              n.box.hi.data()) == -1);
    }
    // And the refit tree finds what a fresh tree finds.
    Bvh<18> fresh(a.tris, y0, y1);
    const Bvh<18> other(moved.tris, moved.x0);
    std::vector<std::pair<int, int>> p1, p2;
    traverse(t, other, p1);
    traverse(fresh, other, p2);
    std::sort(p1.begin(), p1.end());
    std::sort(p2.begin(), p2.end());
    RC_ASSERT(p1 == p2);
  }));
}

// traverse_self (the cloth against itself) reports each unordered pair of distinct primitives
// that traverse(t, t) reports, once, and nothing else; so it too contains the brute force.
template <int K>
void check_self(const Soup& a, int leaf_size) {
  const Bvh<K> t(a.tris, a.x0, a.x1, leaf_size);
  std::vector<std::pair<int, int>> self, both;
  traverse_self(t, self);
  traverse(t, t, both);
  std::set<std::pair<int, int>> got;
  for (const auto& [p, q] : self) {
    RC_ASSERT(p != q);
    RC_ASSERT(got.insert(std::minmax(p, q)).second);  // once
  }
  std::set<std::pair<int, int>> want;
  for (const auto& [p, q] : both)
    if (p != q) want.insert(std::minmax(p, q));
  RC_ASSERT(got == want);
}

TEST(BvhProperties, SelfTraversalEqualsTraversalAgainstItself) {
  EXPECT_TRUE(rc::check("self-traversal", [] {
    const Soup a = *gen_soup(24);
    const int leaf_size = *rc::gen::element(1, 4);
    check_self<6>(a, leaf_size);
    check_self<18>(a, leaf_size);
    check_self<26>(a, leaf_size);
  }));
}

// The cloth's tree: one swept point per leaf (refit's one-point path). After a refit to new
// positions, every leaf contains the exact FDH of its point at both ends of the step.
TEST(BvhProperties, PointTreeRefitContainsTheExactSweep) {
  EXPECT_TRUE(rc::check("point-tree-refit", [] {
    const Soup a = *gen_soup(24), moved = *gen_soup(24);
    if (moved.x0.size() < a.x0.size()) return;
    const std::vector<Vec3> y0(moved.x0.begin(), moved.x0.begin() + a.x0.size()),
        y1(moved.x1.begin(), moved.x1.begin() + a.x0.size());
    Bvh<26> t(point_prims(int(a.x0.size())), a.x0, a.x1);
    t.refit(y0, y1);
    for (const auto& n : t.nodes()) {
      if (!n.leaf()) continue;
      const int i = t.tris()[t.prims()[n.first]][0];
      const Vec3 pts[2] = {y0[i], y1[i]};
      RC_ASSERT(exact::first_uncontained_slab(26, pts, 2, n.box.lo.data(), n.box.hi.data()) == -1);
    }
  }));
}

}  // namespace
}  // namespace fdh

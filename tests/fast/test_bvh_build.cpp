// The FDH tree built with its subtrees spread (Bvh's spread constructor: the audit builds them
// on every core) is the tree built in order, node for node, for any order the subtrees are
// built in, any leaf size and k; and its nodes are in preorder (a node's left child next, its
// right child after the left subtree).
#include <gtest/gtest.h>

#include <random>

#include "fdh/bvh.hpp"
#include "fdh/parallel/chunks.hpp"

namespace fdh {
namespace {

struct BuildSoup {
  std::vector<Tri> tris;
  std::vector<Vec3> x0, x1;
};

BuildSoup soup(int triangles, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  BuildSoup s;
  for (int i = 0; i < 3 * triangles; ++i) {
    s.x0.push_back({u(rng), u(rng), u(rng)});
    s.x1.push_back(s.x0.back() + Vec3{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)});
  }
  for (int i = 0; i < triangles; ++i) s.tris.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  return s;
}

template <int K>
void expect_same_tree(const Bvh<K>& a, const Bvh<K>& b) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  EXPECT_EQ(a.prims(), b.prims());
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    const auto &p = a.nodes()[i], &q = b.nodes()[i];
    ASSERT_EQ(std::tie(p.left, p.right, p.first, p.count),
              std::tie(q.left, q.right, q.first, q.count))
        << "node " << i;
    ASSERT_EQ(p.box.lo, q.box.lo) << "node " << i;
    ASSERT_EQ(p.box.hi, q.box.hi) << "node " << i;
  }
}

// Preorder: node i's left child is i + 1 and its right child follows the left subtree.
template <int K>
int check_preorder(const Bvh<K>& t, int i) {
  const auto& n = t.nodes()[std::size_t(i)];
  if (n.leaf()) return i + 1;
  EXPECT_EQ(n.left, i + 1);
  const int right = check_preorder(t, n.left);
  EXPECT_EQ(n.right, right);
  return check_preorder(t, right);
}

template <int K>
void check(const BuildSoup& s, int leaf_size) {
  const Bvh<K> in_order(s.tris, s.x0, s.x1, leaf_size);
  EXPECT_EQ(check_preorder(in_order, 0), int(in_order.nodes().size()));
  int spread_count = 0;
  const Bvh<K> reversed(s.tris, s.x0, s.x1, leaf_size, [&](int n, const auto& f) {
    spread_count = n;
    for (int i = n - 1; i >= 0; --i) f(i);
  });
  EXPECT_EQ(spread_count, std::min<int>(64, int(in_order.nodes().size() + 1) / 2));
  expect_same_tree(in_order, reversed);
  const Bvh<K> cores(s.tris, s.x0, s.x1, leaf_size, [](int n, const auto& f) {
    parallel::for_each_index(std::size_t(n), 1, [&](std::size_t i) { f(int(i)); });
  });
  expect_same_tree(in_order, cores);
}

TEST(BvhBuild, SpreadSubtreesGiveTheTreeBuiltInOrder) {
  for (const int triangles : {1, 2, 3, 63, 64, 65, 1000, 5001}) {
    const BuildSoup s = soup(triangles, unsigned(triangles));
    for (const int leaf_size : {1, 3}) {
      SCOPED_TRACE(::testing::Message() << triangles << " triangles, leaf size " << leaf_size);
      check<6>(s, leaf_size);
      check<18>(s, leaf_size);
    }
  }
}

}  // namespace
}  // namespace fdh

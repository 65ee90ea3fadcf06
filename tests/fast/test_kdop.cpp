#include "fdh/kdop.hpp"

#include <gtest/gtest.h>

#include "fdh/exact/kdop.hpp"

namespace fdh {
namespace {

template <int K>
int uncontained(const std::vector<Vec3>& pts) {
  const Kdop<K> b = kdop_of<K>(pts.data(), pts.size());
  return exact::first_uncontained_slab(K, pts.data(), pts.size(), b.lo.data(), b.hi.data());
}

TEST(Kdop, DirectionSetsMatchK) {
  EXPECT_EQ(direction_indices<6>().size(), 3u);
  EXPECT_EQ(direction_indices<14>()[6], 6);
  EXPECT_EQ(direction_indices<18>()[3], 7);
  EXPECT_EQ(direction_indices<26>()[12], 12);
  const Direction d = slab_direction(18, 3);
  EXPECT_EQ(d.x, 1);
  EXPECT_EQ(d.y, 1);
  EXPECT_EQ(d.z, 0);
}

// 2^53 + 1 is not a double: a naive x + y rounds to 2^53 and would cut the exact FDH.
TEST(Kdop, DiagonalSlabIsRoundedOutward) {
  const std::vector<Vec3> pts = {{0x1p53, 1, 0}, {-3, 0.5, 2}};
  const Kdop<18> b = kdop_of<18>(pts.data(), pts.size());
  const int xy = 3;  // (1,1,0) is the first edge diagonal
  EXPECT_GT(b.hi[xy], 0x1p53);
  EXPECT_EQ(uncontained<18>(pts), -1);
  EXPECT_EQ(uncontained<26>(pts), -1);
}

TEST(Kdop, NaiveRoundingIsNotConservative) {
  // What FCL-style code computes: the rounded sum itself. The exact reference catches it.
  const std::vector<Vec3> pts = {{0x1p53, 1, 0}};
  Kdop<18> naive = Kdop<18>::empty();
  for (int s = 0; s < 9; ++s) naive.lo[s] = naive.hi[s] = project(Kdop<18>::direction(s), pts[0]);
  EXPECT_EQ(exact::first_uncontained_slab(18, pts.data(), 1, naive.lo.data(), naive.hi.data()), 3);
}

TEST(Kdop, OverlapIsClosedAndEarlyOutAgrees) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 1, 1}}, b = {{1, 1, 1}, {2, 2, 2}},
                          c = {{1.5, 1.5, 1.5}, {2, 2, 2}};
  const Kdop<26> ka = kdop_of<26>(a.data(), 2), kb = kdop_of<26>(b.data(), 2),
                 kc = kdop_of<26>(c.data(), 2);
  EXPECT_TRUE(overlap(ka, kb));
  EXPECT_FALSE(overlap(ka, kc));
  for (int s = 0; s < 13; ++s) {
    EXPECT_TRUE(overlap(ka, kb, s));
    EXPECT_FALSE(overlap(ka, kc, s));
  }
}

TEST(Kdop, MostAlignedSlabOfAFall) {
  EXPECT_EQ(most_aligned_slab<14>(Vec3{0, -9.8, 0}), 1);
  EXPECT_EQ(Kdop<26>::direction(most_aligned_slab<26>(Vec3{1, 1.1, 0.9})).z, 1);
}

TEST(Kdop, BadKIsAnError) {
  EXPECT_THROW(with_k(8, [](auto) { return 0; }), std::invalid_argument);
}

}  // namespace
}  // namespace fdh

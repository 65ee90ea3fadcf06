// Properties 1 and 2: the float FDH contains the exact FDH, for every k; so the float overlap
// test never says "disjoint" when the exact FDHs overlap.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>

#include "fdh/exact/kdop.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "fdh/kdop.hpp"

namespace fdh {
namespace {

// Any double with |x| in [2^-60, 2^41), all 53 bits random: the sums round.
rc::Gen<double> wide_double() {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([] {
                           const auto mant = *rc::gen::inRange<std::int64_t>(std::int64_t(1) << 52,
                                                                             std::int64_t(1) << 53);
                           const int e = *rc::gen::inRange(-60, 41);
                           const double sign = *rc::gen::element(-1.0, 1.0);
                           return sign * std::ldexp(double(mant), e - 53);
                         }));
}

// A cloud of 1 to 8 points: near the origin, or 2^20 to 2^40 from it with small spread.
rc::Gen<std::vector<Vec3>> cloud() {
  return rc::gen::resize(
      rc::kNominalSize, rc::gen::exec([] {
        const int n = *rc::gen::inRange(1, 9);
        const bool far = *rc::gen::arbitrary<bool>();
        const Vec3 centre = far ? Vec3{std::ldexp(1.0, *rc::gen::inRange(20, 41)),
                                       -std::ldexp(1.0, *rc::gen::inRange(20, 41)),
                                       std::ldexp(3.0, *rc::gen::inRange(20, 41))}
                                : Vec3{};
        std::vector<Vec3> pts;
        for (int i = 0; i < n; ++i)
          pts.push_back(centre + Vec3{*wide_double(), *wide_double(), *wide_double()});
        return pts;
      }));
}

template <int K>
bool contains_exact(const std::vector<Vec3>& pts) {
  const Kdop<K> b = kdop_of<K>(pts.data(), pts.size());
  const int s = exact::first_uncontained_slab(K, pts.data(), pts.size(), b.lo.data(), b.hi.data());
  if (s >= 0) RC_LOG() << "k = " << K << ", slab " << s << " does not contain the exact extent\n";
  return s < 0;
}

bool contains_for_every_k(const std::vector<Vec3>& pts) {
  return contains_exact<6>(pts) && contains_exact<14>(pts) && contains_exact<18>(pts) &&
         contains_exact<26>(pts);
}

TEST(KdopProperties, FloatFdhContainsExactFdh) {
  EXPECT_TRUE(rc::check("contains/clouds", [] { RC_ASSERT(contains_for_every_k(*cloud())); }));
  for (const verify::Family& f : verify::all_families()) {
    if (f.moving) continue;  // the static vertex-face families
    EXPECT_TRUE(rc::check("contains/" + f.name, [&f] {
      const Query q = (*verify::gen_family(f)).query;
      RC_ASSERT(contains_for_every_k(std::vector<Vec3>(q.x.begin(), q.x.end())));
    }));
  }
}

template <int K>
void assert_no_false_disjoint(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (!exact::kdops_overlap(K, a.data(), a.size(), b.data(), b.size())) return;
  const Kdop<K> ka = kdop_of<K>(a.data(), a.size()), kb = kdop_of<K>(b.data(), b.size());
  RC_ASSERT(overlap(ka, kb));
  for (int s = 0; s < Kdop<K>::kSlabs; ++s) RC_ASSERT(overlap(ka, kb, s));
}

void assert_no_false_disjoint_any_k(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  assert_no_false_disjoint<6>(a, b);
  assert_no_false_disjoint<14>(a, b);
  assert_no_false_disjoint<18>(a, b);
  assert_no_false_disjoint<26>(a, b);
}

TEST(KdopProperties, OverlapNeverSaysDisjointWhenExactOverlaps) {
  // The sweep BB' against the triangle: touching is common in these families.
  for (const verify::Family& f : verify::all_families()) {
    if (f.moving) continue;
    EXPECT_TRUE(rc::check("overlap/" + f.name, [&f] {
      const Query q = (*verify::gen_family(f)).query;
      assert_no_false_disjoint_any_k({q.b0(), q.b1()}, {q.d(), q.e(), q.f()});
    }));
  }
  // A cloud against a copy of itself moved by a hair: touching slabs after rounding.
  EXPECT_TRUE(rc::check("overlap/nudged-clouds", [] {
    const std::vector<Vec3> a = *cloud();
    const Vec3 nudge{*wide_double(), *wide_double(), *wide_double()};
    const int shift = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 60));
    std::vector<Vec3> b;
    for (const Vec3& p : a) b.push_back(p + std::ldexp(1.0, -shift) * nudge);
    assert_no_false_disjoint_any_k(a, b);
  }));
}

}  // namespace
}  // namespace fdh

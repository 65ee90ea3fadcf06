// The exact CCD's polynomial algebra (reference/src/polynomial.hpp) on polynomials whose roots
// are known by construction: products of up to six (kMaxDegree) linear factors (q t - p), with
// roots at 0, at 1, at dyadic points, at non-dyadic rationals, outside [0, 1], repeated (multiple
// roots) and shared with a second polynomial (common roots). Checks the roots in [0, 1] (all of
// them, in order, each in its interval), the Bernstein no-root test, and the exact sign of a second
// polynomial at each root, against GMP rationals.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "polynomial.hpp"

namespace fdh::exact::algebra {
namespace {

struct Rational {
  long p, q;  // p / q, q > 0
};

// The product of (q t - p) over the roots, times `scale`.
Poly product(const std::vector<Rational>& roots, long scale) {
  Poly out(Coeffs{Int(scale)});
  for (const Rational& r : roots) out = out * Poly(Coeffs{Int(-r.p), Int(r.q)});
  return out;
}

mpq_class value(const Poly& p, const mpq_class& t) {
  mpq_class v = 0;
  for (std::size_t i = p.c.size(); i-- > 0;) v = v * t + mpq_class(p.c[i].to_mpz());
  return v;
}

// Roots at 0, 1, dyadic points, thirds and fifths, and outside [0, 1].
Rational random_root(std::mt19937& rng) {
  static const Rational kRoots[] = {{0, 1},  {1, 1},  {1, 2}, {3, 8},  {1, 3}, {2, 3},   {2, 5},
                                    {7, 16}, {-1, 2}, {3, 2}, {5, 11}, {9, 7}, {1, 1024}};
  return kRoots[std::uniform_int_distribution<int>(0, 12)(rng)];
}

TEST(Polynomial, RootsInTheUnitIntervalAreTheConstructedOnes) {
  std::mt19937 rng(20261125);
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = std::uniform_int_distribution<int>(1, kMaxDegree)(rng);
    std::vector<Rational> roots;
    for (int i = 0; i < n; ++i)  // repeats make multiple roots
      roots.push_back(i > 0 && rng() % 3 == 0 ? roots[rng() % roots.size()] : random_root(rng));
    const long scale = rng() % 2 ? 1 : -3;
    Poly s = product(roots, scale);
    const Poly p = s;
    std::vector<mpq_class> want;  // the distinct roots in [0, 1], increasing
    for (const Rational& r : roots) {
      const mpq_class x(r.p, r.q);
      if (x >= 0 && x <= 1) want.push_back(x);
    }
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());

    EXPECT_FALSE(!want.empty() && no_root_in_unit(p)) << "trial " << trial;
    Roots got = roots_in(s, Dyadic::of(0), Dyadic::of(1));
    ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
    // A second polynomial sharing the first root in [0, 1], and one positive at none of them.
    std::vector<Rational> other{roots[0], {5, 4}};
    const Poly g = product(other, 2), h = product({{-1, 1}, {-2, 1}}, 1) - Poly(Coeffs{Int(9)});
    for (std::size_t i = 0; i < got.size(); ++i) {
      Root& r = got[i];
      const mpq_class lo = r.lo().value(), hi = r.hi().value();
      if (r.exact())
        EXPECT_EQ(lo, want[i]) << "trial " << trial;
      else
        EXPECT_TRUE(lo < want[i] && want[i] < hi) << "trial " << trial;
      EXPECT_EQ(sign_at(g, r), sgn(value(g, want[i]))) << "trial " << trial;
      EXPECT_EQ(sign_at(h, r), sgn(value(h, want[i]))) << "trial " << trial;
      refine(r, 40);
      EXPECT_TRUE(r.lo().value() <= want[i] && want[i] <= r.hi().value());
      EXPECT_LT(r.hi().value() - r.lo().value(), mpq_class(1, 1) / (mpz_class(1) << 40));
    }
  }
}

TEST(Polynomial, NoRootInTheUnitIntervalIsNeverWrongAndOftenDecides) {
  std::mt19937 rng(7);
  int decided = 0, without = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = std::uniform_int_distribution<int>(1, kMaxDegree)(rng);
    std::vector<Rational> roots;
    for (int i = 0; i < n; ++i) roots.push_back(random_root(rng));
    // A small constant added moves the roots: Sturm sequences (roots_in) decide instead.
    Poly p = product(roots, 1) + Poly(Coeffs{Int(long(rng() % 3))});
    if (p.degree() < 1) continue;
    Poly s = p;
    const bool none = roots_in(s, Dyadic::of(0), Dyadic::of(1)).empty();
    if (no_root_in_unit(p)) {
      EXPECT_TRUE(none) << "trial " << trial;
    }
    if (n > 4) continue;  // degree 5-6 (minimum separation): safety only, the test decides less
    without += none;
    decided += none && no_root_in_unit(p);
  }
  EXPECT_GT(decided, without / 2);  // the test is of use on contact's degrees, not only safe
}

// The unit window isolates by Bernstein bisection (Sturm only when that does not finish); the
// halves [0, 1/2] and [1/2, 1] always use Sturm sequences. Random small coefficients give
// complex pairs, close and double roots and roots at the ends (and at 1/2, where bisection
// splits), so both must count the same roots, and p must change sign across each interval.
TEST(Polynomial, UnitWindowCountsTheRootsOfItsHalves) {
  std::mt19937 rng(11);
  int one_root = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Coeffs c;
    for (int i = 0, n = 2 + int(rng() % 4); i < n; ++i) c.push_back(Int(long(rng() % 41) - 20));
    Poly p(c);
    if (p.degree() < 1) continue;
    Poly s = p, s0 = p, s1 = p;
    const Roots all = roots_in(s, Dyadic::of(0), Dyadic::of(1));
    const Dyadic half = Dyadic::of(0.5);
    const Roots left = roots_in(s0, Dyadic::of(0), half), right = roots_in(s1, half, Dyadic::of(1));
    const bool shared = !left.empty() && left.back().exact() && left.back().lo().value() == 0.5;
    EXPECT_EQ(all.size(), left.size() + right.size() - shared) << "trial " << trial;
    for (const Root& r : all) {
      if (!r.exact()) {
        EXPECT_LT(sign_at(p, r.lo()) * sign_at(p, r.hi()), 0) << "trial " << trial;
      }
    }
    one_root += all.size() == 1;
  }
  EXPECT_GT(one_root, 300);  // the one-root case is exercised
}

TEST(Polynomial, DyadicOfADoubleIsExactWithTheFewestBits) {
  for (const double x : {0.0, 1.0, 0.5, -3.75, 0.1, -1e-17, 1e300, -0x1.fffffffffffffp+1023,
                         0x1p-1074, 0x1.8p-1070, 0x1p-1022, 3.0 * 0x1p60, 0x1.c8p-4}) {
    const Dyadic d = Dyadic::of(x);
    EXPECT_EQ(d.value(), mpq_class(x)) << x;
    // a odd unless k = 0: no factor of two left to drop
    if (d.k > 0) {
      EXPECT_TRUE(mpz_odd_p(d.a.to_mpz().get_mpz_t())) << x;
    }
  }
}

TEST(Polynomial, InlineVectorRefusesMoreThanItsCapacity) {
  Coeffs c(kMaxDegree + 1);
  EXPECT_THROW(c.push_back(Int(1)), std::length_error);
  EXPECT_THROW(c.resize(kMaxDegree + 2), std::length_error);
  c.resize(2);
  c[1] = Int(7);
  const Coeffs d = c;
  EXPECT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1], Int(7));
}

}  // namespace
}  // namespace fdh::exact::algebra

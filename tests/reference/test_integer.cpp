// Int (reference/src/integer.hpp): every operation equals GMP's, on values on both sides of the
// machine fast path's limits (2^63, 2^64, 2^126, 2^127), of the inline limbs (2^768) and of the
// stack buffers (products beyond 48 limbs, 3072 bits), so that no size check is off by one.
#include <gtest/gtest.h>

#include <vector>

#include "integer.hpp"

namespace fdh::exact::algebra {
namespace {

std::vector<mpz_class> samples() {
  std::vector<mpz_class> out;
  for (const unsigned long e : {0ul, 1ul, 31ul, 62ul, 63ul, 64ul, 65ul, 125ul, 126ul, 127ul, 128ul,
                                200ul, 383ul, 384ul, 767ul, 768ul, 769ul, 1600ul}) {
    const mpz_class p = mpz_class(1) << e;
    for (const mpz_class& v :
         {mpz_class(p), mpz_class(p - 1), mpz_class(p + 1), mpz_class(3 * p)}) {
      out.push_back(v);
      out.push_back(-v);
    }
  }
  out.push_back(0);
  out.push_back(mpz_class("123456789012345678901234567"));
  out.push_back(mpz_class("-98765432109876543210987654321098765"));
  return out;
}

void expect_equal(const Int& got, const mpz_class& want, const char* what, const mpz_class& a,
                  const mpz_class& b) {
  EXPECT_EQ(got.to_mpz(), want) << what << " of " << a.get_str() << " and " << b.get_str();
  EXPECT_EQ(got.sign(), sgn(want)) << what;
}

TEST(Integer, ArithmeticEqualsGmp) {
  const std::vector<mpz_class> v = samples();
  for (const mpz_class& a : v)
    for (const mpz_class& b : v) {
      const Int x(a), y(b);
      expect_equal(x + y, a + b, "sum", a, b);
      expect_equal(x - y, a - b, "difference", a, b);
      expect_equal(x * y, a * b, "product", a, b);
      EXPECT_EQ(compare(x, y), (a > b) - (a < b));
      EXPECT_EQ(compare_abs(x, y), (abs(a) > abs(b)) - (abs(a) < abs(b)));
      mpz_class g;
      mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
      expect_equal(gcd(x, y), g, "gcd", a, b);
      if (b != 0) expect_equal(divexact(x * y, y), a, "exact quotient", a, b);
      Int r = x, s = x, m;
      addmul(r, x, y), submul(s, x, y), mul(m, x, y);
      expect_equal(r, a + a * b, "addmul", a, b);
      expect_equal(s, a - a * b, "submul", a, b);
      expect_equal(m, a * b, "mul", a, b);
      mul(m, m, y);  // the result aliasing an operand
      expect_equal(m, a * b * b, "mul in place", a, b);
      Int t = x, u = x;
      addmul(t, t, y), submul(u, y, u);
      expect_equal(t, a + a * b, "addmul in place", a, b);
      expect_equal(u, a - b * a, "submul in place", a, b);
    }
}

TEST(Integer, ShiftsAndDoublesEqualGmp) {
  for (const mpz_class& a : samples()) {
    const Int x(a);
    for (const unsigned long k :
         {0ul, 1ul, 2ul, 63ul, 64ul, 100ul, 125ul, 126ul, 130ul, 640ul, 705ul, 1500ul}) {
      const mpz_class want = a << k;
      expect_equal(x << k, want, "shift", a, mpz_class(k));
      Int r = 7;
      mul_2exp(r, x, k);
      expect_equal(r, want, "shift in place", a, mpz_class(k));
    }
    long e = 0, f = 0;
    const double m = x.frexp(&e), n = mpz_get_d_2exp(&f, a.get_mpz_t());
    EXPECT_EQ(m, n) << a.get_str();
    EXPECT_EQ(e, f) << a.get_str();
  }
}

TEST(Integer, CopiesAndMovesKeepTheValue) {
  for (const mpz_class& a : samples()) {
    Int x(a);
    Int y = x;
    Int z = std::move(x);
    EXPECT_EQ(y.to_mpz(), a);
    EXPECT_EQ(z.to_mpz(), a);
    y = Int(5);
    y = z;
    EXPECT_EQ(y.to_mpz(), a);
    z = std::move(y);
    EXPECT_EQ(z.to_mpz(), a);
  }
}

}  // namespace
}  // namespace fdh::exact::algebra

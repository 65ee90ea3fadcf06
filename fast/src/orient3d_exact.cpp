#include "fdh/orient3d_exact.hpp"

#include <cmath>

#include "fdh/dyadic.hpp"

namespace fdh {
namespace {

// a b = p + e exactly, for a, b and a b far from overflow and underflow (Shewchuk 1997,
// Theorem 18: Dekker's product of Veltkamp's halves, each product of halves exact). Where a
// fused multiply-add is fast, e is fma(a, b, -p), exact by definition; there the compiler could
// also fuse Dekker's own steps and break them, so he is used only where it cannot.
void two_product(double a, double b, double& p, double& e) {
  p = a * b;
#ifdef FP_FAST_FMA
  e = std::fma(a, b, -p);
#else
  const auto halves = [](double x, double& hi, double& lo) {
    const double c = 134217729.0 * x;  // 2^27 + 1
    hi = c - (c - x);
    lo = x - hi;
  };
  double ah, al, bh, bl;
  halves(a, ah, al);
  halves(b, bh, bl);
  e = al * bl - (((p - ah * bh) - al * bh) - ah * bl);
#endif
}

// A sum of doubles kept exactly as a nonoverlapping expansion, components in increasing
// magnitude, zeros dropped (Shewchuk 1997, Grow-Expansion, Theorem 10, with zero elimination).
// Its sign is that of its largest component.
class Expansion {
 public:
  void add(double x) {
    int m = 0;
    for (int i = 0; i < n_; ++i) {
      double e;
      two_sum(x, c_[i], x, e);
      if (e != 0) c_[m++] = e;
    }
    if (x != 0) c_[m++] = x;
    n_ = m;
  }
  int sign() const { return n_ == 0 ? 0 : (c_[n_ - 1] > 0 ? 1 : -1); }

 private:
  static constexpr int kMax = 24;  // six terms of four components: one more each at most
  double c_[kMax];
  int n_ = 0;
};

// x = a - b exactly, within the range where two_product is exact.
bool exact_difference(double a, double b, double& x) {
  if (!add_exactly(a, -b, x)) return false;
  const double m = std::fabs(x);
  return m == 0 || (m >= 0x1p-300 && m <= 0x1p100);
}

bool exact_difference(const Vec3& a, const Vec3& b, Vec3& x) {
  return exact_difference(a.x, b.x, x.x) && exact_difference(a.y, b.y, x.y) &&
         exact_difference(a.z, b.z, x.z);
}

// s a b c added exactly: a b = h + l, then h c and l c, two components each. Every factor is 0
// or in [2^-300, 2^100], so no product overflows and every product's bits lie above 2^-1074.
void add_product(Expansion& sum, double s, double a, double b, double c) {
  double h, l, p, e;
  two_product(s * a, b, h, l);
  two_product(h, c, p, e);
  sum.add(e), sum.add(p);
  two_product(l, c, p, e);
  sum.add(e), sum.add(p);
}

}  // namespace

bool exact_volume_sign(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, int& sign) {
  Vec3 u, v, w;
  if (!exact_difference(p1, p0, u) || !exact_difference(p2, p0, v) || !exact_difference(p3, p0, w))
    return false;
  // det(u, v, w) by its six terms.
  Expansion sum;
  add_product(sum, 1, u.x, v.y, w.z);
  add_product(sum, -1, u.x, v.z, w.y);
  add_product(sum, 1, u.y, v.z, w.x);
  add_product(sum, -1, u.y, v.x, w.z);
  add_product(sum, 1, u.z, v.x, w.y);
  add_product(sum, -1, u.z, v.y, w.x);
  sign = sum.sign();
  return true;
}

}  // namespace fdh

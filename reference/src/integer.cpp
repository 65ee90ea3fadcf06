#include "integer.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <utility>

namespace fdh::exact::algebra {
namespace {

using Size = mp_size_t;  // a signed limb count, GMP's convention: negative for negative values

// Room for n limbs for one result: on the stack for the CCD's sizes, on the heap beyond (the
// pseudo-remainders of a gcd can reach a few thousand bits).
class Buffer {
 public:
  explicit Buffer(Size n)
      : data_(n <= kStack ? stack_ : (heap_ = std::make_unique<mp_limb_t[]>(n)).get()) {}
  mp_limb_t* data() { return data_; }

 private:
  static constexpr Size kStack = 48;
  mp_limb_t stack_[kStack];
  std::unique_ptr<mp_limb_t[]> heap_;
  mp_limb_t* data_;
};

// r = x + y on magnitudes with signed sizes. r has room for max(|xn|, |yn|) + 1 limbs; it may be
// x or y (GMP's mpn functions allow exact overlap, not partial). Returns r's signed size.
Size add_limbs(mp_limb_t* r, const mp_limb_t* x, Size xn, const mp_limb_t* y, Size yn) {
  Size ax = std::abs(xn), ay = std::abs(yn);
  const bool same_sign = (xn < 0) == (yn < 0);
  // Make |x| >= |y| (by length alone when the magnitudes add).
  if (ax < ay || (ax == ay && !same_sign && ax > 0 && mpn_cmp(x, y, ax) < 0))
    std::swap(x, y), std::swap(xn, yn), std::swap(ax, ay);
  if (ay == 0) {
    std::copy(x, x + ax, r);
    return xn;
  }
  Size n = ax;
  if (same_sign) {
    r[ax] = mpn_add(r, x, ax, y, ay);
    n += r[ax] != 0;
  } else {
    mpn_sub(r, x, ax, y, ay);
    while (n > 0 && r[n - 1] == 0) --n;
  }
  return xn < 0 ? -n : n;
}

// r = x y with signed sizes. r has room for |xn| + |yn| limbs and overlaps neither operand.
Size multiply_limbs(mp_limb_t* r, const mp_limb_t* x, Size xn, const mp_limb_t* y, Size yn) {
  Size ax = std::abs(xn), ay = std::abs(yn);
  if (ax == 0 || ay == 0) return 0;
  if (ax < ay) std::swap(x, y), std::swap(ax, ay);  // mpn_mul wants the longer one first
  if (ax <= 2) {  // schoolbook on 64-bit halves of 128-bit products: no call into GMP
    using u128 = unsigned __int128;
    const u128 p00 = u128(x[0]) * y[0];
    const u128 p10 = ax == 2 ? u128(x[1]) * y[0] : 0, p01 = ay == 2 ? u128(x[0]) * y[1] : 0;
    const u128 p11 = ay == 2 ? u128(x[1]) * y[1] : 0;
    const u128 mid = (p00 >> 64) + mp_limb_t(p10) + mp_limb_t(p01);  // < 3 2^64: no overflow
    const u128 high = (mid >> 64) + (p10 >> 64) + (p01 >> 64) + mp_limb_t(p11);
    const mp_limb_t d[4] = {mp_limb_t(p00), mp_limb_t(mid), mp_limb_t(high),
                            mp_limb_t(high >> 64) + mp_limb_t(p11 >> 64)};
    for (Size i = 0; i < ax + ay; ++i) r[i] = d[i];  // a call to memmove costs more
  } else if (ay == 1) {
    r[ax] = mpn_mul_1(r, x, ax, y[0]);
  } else {
    mpn_mul(r, x, ax, y, ay);
  }
  const Size n = ax + ay - (r[ax + ay - 1] == 0);
  return (xn < 0) != (yn < 0) ? -n : n;
}

int sign_of(int c) {
  return (c > 0) - (c < 0);
}

}  // namespace

Int::Int(long v) {
  if (v == 0) return;
  inline_[0] = v < 0 ? 0 - mp_limb_t(v) : mp_limb_t(v);  // also for the most negative v
  size_ = v < 0 ? -1 : 1;
}

Int::Int(const mpz_class& z) {
  assign(z.get_mpz_t());
}

void Int::assign(const mp_limb_t* d, int n, bool negative) {
  while (n > 0 && d[n - 1] == 0) --n;
  if (n > capacity_) {  // d cannot be ours then
    const int grown = std::max(n, 2 * capacity_);
    delete[] heap_;
    heap_ = new mp_limb_t[std::size_t(grown)];
    capacity_ = grown;
  }
  mp_limb_t* to = heap_ ? heap_ : inline_;
  for (int i = 0; i < n; ++i) to[i] = d[i];  // a few limbs: cheaper than a call to memmove
  size_ = negative ? -n : n;
}

void Int::assign(mpz_srcptr z) {
  assign(mpz_limbs_read(z), int(mpz_size(z)), mpz_sgn(z) < 0);
}

mpz_srcptr Int::view(mpz_ptr scratch) const {
  return mpz_roinit_n(scratch, limbs(), size_);
}

mpz_class Int::to_mpz() const {
  mpz_t v;
  return mpz_class(view(v));
}

double Int::frexp(long* e) const {
  if (size_ == 0) return *e = 0, 0.0;
  mpz_t v;
  return mpz_get_d_2exp(e, view(v));
}

template <class Limbs>
void Int::write_limbs(Int& r, long room, bool in_place, Limbs limbs) {
  if (in_place && room <= r.capacity_) {
    r.size_ = int(limbs(r.data()));
    return;
  }
  Buffer s(room);
  const Size n = limbs(s.data());
  r.assign(s.data(), int(std::abs(n)), n < 0);
}

void Int::sum_limbs(Int& r, const Int& a, const Int& b, bool subtract) {
  const Size bn = subtract ? -Size(b.size_) : b.size_;
  // r may be a or b: add_limbs reads each limb before it writes it (GMP's exact overlap).
  write_limbs(r, std::max(a.length(), b.length()) + 1, true,
              [&](mp_limb_t* d) { return add_limbs(d, a.limbs(), a.size_, b.limbs(), bn); });
}

Int operator+(const Int& a, const Int& b) {
  Int r;
  add(r, a, b);
  return r;
}

Int operator-(const Int& a, const Int& b) {
  Int r;
  sub(r, a, b);
  return r;
}

Int operator*(const Int& a, const Int& b) {
  Int r;
  mul(r, a, b);
  return r;
}

Int operator<<(const Int& a, unsigned long k) {
  Int r;
  mul_2exp(r, a, k);
  return r;
}

Int gcd(const Int& a, const Int& b) {
  thread_local mpz_class g;  // keeps its storage
  mpz_t x, y;
  mpz_gcd(g.get_mpz_t(), a.view(x), b.view(y));
  return Int(g);
}

Int divexact(const Int& a, const Int& b) {
  thread_local mpz_class q;
  mpz_t x, y;
  mpz_divexact(q.get_mpz_t(), a.view(x), b.view(y));
  return Int(q);
}

int compare(const Int& a, const Int& b) {
  if (a.size_ != b.size_) return a.size_ < b.size_ ? -1 : 1;
  if (a.size_ == 0) return 0;  // mpn_* take no empty operands
  const int c = sign_of(mpn_cmp(a.limbs(), b.limbs(), a.length()));
  return a.size_ < 0 ? -c : c;
}

int compare_abs(const Int& a, const Int& b) {
  if (a.length() != b.length()) return a.length() < b.length() ? -1 : 1;
  if (a.size_ == 0) return 0;
  return sign_of(mpn_cmp(a.limbs(), b.limbs(), a.length()));
}

void Int::product_limbs(Int& r, const Int& a, const Int& b) {
  write_limbs(r, a.length() + b.length(), &r != &a && &r != &b, [&](mp_limb_t* d) {
    return multiply_limbs(d, a.limbs(), a.size_, b.limbs(), b.size_);
  });
}

void mul_2exp(Int& r, const Int& a, unsigned long k) {
  const Size n = a.length(), whole = Size(k / GMP_NUMB_BITS);
  const unsigned bits = unsigned(k % GMP_NUMB_BITS);
  if (n == 0) return r.assign(nullptr, 0, false);
  __int128 x;
  if (k < 126 && a.machine(&x)) {  // the machine form while |x| 2^k < 2^126
    using u128 = unsigned __int128;
    const u128 m = x < 0 ? u128(0) - u128(x) : u128(x);
    if (m >> (126 - k) == 0) return r.set(x < 0 ? -__int128(m << k) : __int128(m << k));
  }
  Buffer s(n + whole + 1);
  mp_limb_t* d = s.data();
  std::fill(d, d + whole, mp_limb_t(0));
  if (bits != 0) {
    d[whole + n] = mpn_lshift(d + whole, a.limbs(), n, bits);
  } else {
    std::copy(a.limbs(), a.limbs() + n, d + whole);
    d[whole + n] = 0;
  }
  r.assign(d, int(n + whole + 1), a.size_ < 0);
}

void Int::accumulate_limbs(Int& r, const Int& a, const Int& b, bool subtract) {
  Buffer p(a.length() + b.length());
  Size pn = multiply_limbs(p.data(), a.limbs(), a.size_, b.limbs(), b.size_);
  if (pn == 0) return;
  if (subtract) pn = -pn;
  write_limbs(r, std::max(Size(r.length()), std::abs(pn)) + 1, true,
              [&](mp_limb_t* d) { return add_limbs(d, r.limbs(), r.size_, p.data(), pn); });
}

void negate(Int& r) {
  r.size_ = -r.size_;
}

}  // namespace fdh::exact::algebra

// An exact integer of any size for the exact CCD's algebra (polynomial.hpp): sign and magnitude
// in 64-bit limbs, like a GMP integer, but the limbs live inside the object up to kInline of
// them and on the heap only beyond. Values below 2^127 are added and multiplied as machine
// __int128 with overflow checks. Private to reference/.
//
// Why: scaled by one power of two into integers, the benchmark's coordinates have up to about
// 110 bits and the polynomials built from them (degree 4 in the coordinates) some 450-700;
// GMP's integers allocate every value on the heap, which was about half of the exact test's
// time. The arithmetic is GMP's own low-level layer (mpn_*) on limbs that we own, written
// straight into the result when it has room (GMP allows an exact overlap of result and
// operand), else through a stack buffer, so any operand may alias the result. gcd and exact
// division go through GMP's integers on read-only views of our limbs (mpz_roinit_n).
// tests/reference/test_integer.cpp compares every operation with GMP's around limb boundaries.
#pragma once

#include <gmp.h>
#include <gmpxx.h>

namespace fdh::exact::algebra {

class Int {
 public:
  Int() {}      // 0; the limbs stay uninitialized until used
  Int(long v);  // NOLINT(google-explicit-constructor): converts like an int
  explicit Int(const mpz_class& z);
  // Copies and moves are the hot path of the polynomial code: inline, no allocation up to
  // kInline limbs.
  Int(const Int& o) { copy(o); }
  Int(Int&& o) noexcept { move(o); }
  Int& operator=(const Int& o) {
    if (this != &o) copy(o);
    return *this;
  }
  Int& operator=(Int&& o) noexcept {
    if (this != &o) move(o);
    return *this;
  }
  ~Int() {
    if (heap_ != nullptr) delete[] heap_;
  }

  int sign() const { return (size_ > 0) - (size_ < 0); }
  bool is_zero() const { return size_ == 0; }
  mpz_class to_mpz() const;
  // x = m 2^e with 0.5 <= |m| < 1 (0 for x = 0), m truncated to a double (as mpz_get_d_2exp).
  double frexp(long* e) const;

  friend Int operator+(const Int& a, const Int& b);
  friend Int operator-(const Int& a, const Int& b);
  friend Int operator*(const Int& a, const Int& b);
  friend Int operator<<(const Int& a, unsigned long k);  // a 2^k
  friend Int gcd(const Int& a, const Int& b);            // >= 0
  friend Int divexact(const Int& a, const Int& b);       // a / b, where b divides a
  friend int compare(const Int& a, const Int& b);
  friend int compare_abs(const Int& a, const Int& b);  // compare(|a|, |b|)
  // In place: r = a + b, r = a - b, r = a b, r = a 2^k, r += a b and r -= a b. The building blocks
  // of the hot loops (products of polynomials, Horner); r keeps its storage.
  friend void add(Int& r, const Int& a, const Int& b);
  friend void sub(Int& r, const Int& a, const Int& b);
  friend void mul(Int& r, const Int& a, const Int& b);
  friend void mul_2exp(Int& r, const Int& a, unsigned long k);
  friend void addmul(Int& r, const Int& a, const Int& b);
  friend void submul(Int& r, const Int& a, const Int& b);
  friend void negate(Int& r);  // r = -r

 private:
  static constexpr int kInline = 12;  // 768 bits: the CCD's polynomials, not its gcds

  const mp_limb_t* limbs() const { return heap_ ? heap_ : inline_; }
  mp_limb_t* data() { return heap_ ? heap_ : inline_; }
  int length() const { return size_ < 0 ? -size_ : size_; }
  // Sets the value to the n limbs at d (not ours), negated if `negative`; n may have leading
  // zero limbs.
  void assign(const mp_limb_t* d, int n, bool negative);
  void assign(mpz_srcptr z);
  void copy(const Int& o) {
    const int n = o.length();
    if (n > capacity_) return assign(o.limbs(), n, o.size_ < 0);
    mp_limb_t* to = heap_ ? heap_ : inline_;
    const mp_limb_t* from = o.limbs();
    for (int i = 0; i < n; ++i) to[i] = from[i];
    size_ = o.size_;
  }
  void move(Int& o) noexcept {               // o's heap limbs, if it has some, change owner
    if (o.heap_ == nullptr) return copy(o);  // fits our storage: no allocation
    delete[] heap_;
    heap_ = o.heap_, capacity_ = o.capacity_, size_ = o.size_;
    o.heap_ = nullptr, o.capacity_ = kInline, o.size_ = 0;
  }
  mpz_srcptr view(mpz_ptr scratch) const;  // a read-only GMP view of the limbs
  // r = a + or - b, r += or -= a b, r = a b: the machine fast path inline (the polynomial
  // loops mostly take it), GMP's limbs out of line (the *_limbs, integer.cpp).
  static void sum(Int& r, const Int& a, const Int& b, bool subtract) {
    __int128 x, y, z;
    if (a.machine(&x) && b.machine(&y) &&
        !(subtract ? __builtin_sub_overflow(x, y, &z) : __builtin_add_overflow(x, y, &z)))
      return r.set(z);
    sum_limbs(r, a, b, subtract);
  }
  static void accumulate(Int& r, const Int& a, const Int& b, bool subtract) {
    __int128 x, y, z, xy, t;
    if (r.machine(&x) && a.machine(&y) && b.machine(&z) && !__builtin_mul_overflow(y, z, &xy) &&
        !(subtract ? __builtin_sub_overflow(x, xy, &t) : __builtin_add_overflow(x, xy, &t)))
      return r.set(t);
    accumulate_limbs(r, a, b, subtract);
  }
  static void product(Int& r, const Int& a, const Int& b) {
    __int128 x, y, z;
    if (a.machine(&x) && b.machine(&y) && !__builtin_mul_overflow(x, y, &z)) return r.set(z);
    product_limbs(r, a, b);
  }
  static void sum_limbs(Int& r, const Int& a, const Int& b, bool subtract);
  static void accumulate_limbs(Int& r, const Int& a, const Int& b, bool subtract);
  static void product_limbs(Int& r, const Int& a, const Int& b);
  // r = what `limbs(d)` writes at d (returning GMP's signed size): straight into r's own limbs
  // when `in_place` allows and `room` limbs fit there, else through a buffer (integer.cpp).
  template <class Limbs>
  static void write_limbs(Int& r, long room, bool in_place, Limbs limbs);
  // The machine fast path: most values of the hard families fit 127 bits, and __int128
  // arithmetic with overflow checks (__builtin_*_overflow) beats any call into GMP.
  bool machine(__int128* v) const {  // false if |value| >= 2^127
    const int n = length();
    const mp_limb_t* d = limbs();
    if (n > 2 || (n == 2 && d[1] >> 63 != 0)) return false;
    const __int128 m = n == 0 ? 0 : n == 1 ? __int128(d[0]) : __int128(d[1]) << 64 | d[0];
    *v = size_ < 0 ? -m : m;
    return true;
  }
  void set(__int128 v) {
    using u128 = unsigned __int128;
    const u128 m = v < 0 ? u128(0) - u128(v) : u128(v);  // also for the most negative v
    mp_limb_t* d = heap_ ? heap_ : inline_;
    d[0] = mp_limb_t(m), d[1] = mp_limb_t(m >> 64);
    const int n = d[1] != 0 ? 2 : d[0] != 0 ? 1 : 0;
    size_ = v < 0 ? -n : n;
  }

  int size_ = 0;  // the number of limbs, negated for a negative value (as GMP's _mp_size)
  int capacity_ = kInline;
  mp_limb_t* heap_ = nullptr;  // the limbs when they outgrow inline_ (capacity_ of them)
  mp_limb_t inline_[kInline];
};

Int operator+(const Int& a, const Int& b);
Int operator-(const Int& a, const Int& b);
Int operator*(const Int& a, const Int& b);
Int operator<<(const Int& a, unsigned long k);
Int gcd(const Int& a, const Int& b);
Int divexact(const Int& a, const Int& b);
int compare(const Int& a, const Int& b);
int compare_abs(const Int& a, const Int& b);
void mul_2exp(Int& r, const Int& a, unsigned long k);
void negate(Int& r);

inline void add(Int& r, const Int& a, const Int& b) {
  Int::sum(r, a, b, false);
}
inline void sub(Int& r, const Int& a, const Int& b) {
  Int::sum(r, a, b, true);
}
inline void mul(Int& r, const Int& a, const Int& b) {
  Int::product(r, a, b);
}
inline void addmul(Int& r, const Int& a, const Int& b) {
  Int::accumulate(r, a, b, false);
}
inline void submul(Int& r, const Int& a, const Int& b) {
  Int::accumulate(r, a, b, true);
}

inline Int operator-(const Int& a) {
  Int r = a;
  negate(r);
  return r;
}
inline Int abs(const Int& a) {
  return a.sign() < 0 ? -a : a;
}
inline Int& operator+=(Int& a, const Int& b) {
  return a = a + b;
}
inline Int& operator-=(Int& a, const Int& b) {
  return a = a - b;
}
inline Int& operator*=(Int& a, const Int& b) {
  return a = a * b;
}
inline bool operator==(const Int& a, const Int& b) {
  return compare(a, b) == 0;
}
inline bool operator!=(const Int& a, const Int& b) {
  return compare(a, b) != 0;
}
inline bool operator<(const Int& a, const Int& b) {
  return compare(a, b) < 0;
}
inline bool operator<=(const Int& a, const Int& b) {
  return compare(a, b) <= 0;
}
inline bool operator>(const Int& a, const Int& b) {
  return compare(a, b) > 0;
}
inline bool operator>=(const Int& a, const Int& b) {
  return compare(a, b) >= 0;
}

}  // namespace fdh::exact::algebra

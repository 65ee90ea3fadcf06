// An exact integer of any size for the exact CCD's algebra (polynomial.hpp): a machine
// __int128 while the value fits, a GMP integer from the first operation whose result does not.
// Private to reference/.
//
// Why: scaled by one power of two into integers, the coordinates of handcrafted and generated
// queries have a few to some 30 bits, and the polynomials built from them (degree 4 in the
// coordinates) mostly stay below 2^127 (the benchmark's, up to about 110 bits, mostly do not).
// GMP allocates every integer on the heap, which was most of the exact test's time; a machine
// integer needs no allocation. Every machine operation checks for overflow
// (__builtin_*_overflow) and is done by GMP instead when it would overflow, so no value is ever
// wrong, only some slower. A new result that fits 126 bits takes the machine form again.
// tests/reference/test_integer.cpp compares the operations with GMP's around the boundaries.
#pragma once

#include <gmp.h>
#include <gmpxx.h>

namespace fdh::exact::algebra {

class Int {
 public:
  Int() : small_(0) {}
  Int(long v) : small_(v) {}  // NOLINT(google-explicit-constructor): converts like an int
  explicit Int(const mpz_class& z);
  Int(const Int& o);
  Int(Int&& o) noexcept;
  Int& operator=(const Int& o);
  Int& operator=(Int&& o) noexcept;
  ~Int();

  int sign() const { return big_ ? mpz_sgn(&z_) : (small_ > 0) - (small_ < 0); }
  bool is_zero() const { return sign() == 0; }
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
  // In place: r = a b, r = a 2^k, r += a b and r -= a b. A result in GMP form keeps its storage
  // (no allocation), the building blocks of the hot loops (products of polynomials, Horner).
  friend void mul(Int& r, const Int& a, const Int& b);
  friend void mul_2exp(Int& r, const Int& a, unsigned long k);
  friend void addmul(Int& r, const Int& a, const Int& b);
  friend void submul(Int& r, const Int& a, const Int& b);

 private:
  static Int of(__int128 v) { return Int(Small{v}); }
  struct Small {
    __int128 v;
  };
  explicit Int(Small s) : small_(s.v) {}
  // a op b by `machine` (false: no overflow) or else by `gmp` (integer.cpp only).
  template <class Machine, class Gmp>
  static Int binary(const Int& a, const Int& b, Machine machine, Gmp gmp);
  static void accumulate(Int& r, const Int& a, const Int& b, bool subtract);  // r += or -= a b
  mpz_ptr make_big();    // switches to the GMP form (same value) and returns it
  void set(__int128 v);  // keeps the GMP form (and its storage) if it has one
  void shrink();         // back to the machine form if the value fits 126 bits
  // GMP's view of x: its own integer, or its machine value written into `scratch`.
  static mpz_srcptr view(const Int& x, mpz_ptr scratch);

  bool big_ = false;
  union {
    __int128 small_;
    __mpz_struct z_;  // initialized exactly when big_
  };
};

Int operator+(const Int& a, const Int& b);
Int operator-(const Int& a, const Int& b);
Int operator*(const Int& a, const Int& b);
Int operator<<(const Int& a, unsigned long k);
Int gcd(const Int& a, const Int& b);
Int divexact(const Int& a, const Int& b);
int compare(const Int& a, const Int& b);
int compare_abs(const Int& a, const Int& b);
void mul(Int& r, const Int& a, const Int& b);
void mul_2exp(Int& r, const Int& a, unsigned long k);
void addmul(Int& r, const Int& a, const Int& b);
void submul(Int& r, const Int& a, const Int& b);

inline Int operator-(const Int& a) {
  return Int(0) - a;
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

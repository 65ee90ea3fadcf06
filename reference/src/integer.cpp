#include "integer.hpp"

#include <cmath>
#include <cstdint>
#include <utility>

namespace fdh::exact::algebra {
namespace {

using u128 = unsigned __int128;
static_assert(GMP_NUMB_BITS == 64, "the machine form converts 64-bit limbs");

u128 magnitude(__int128 v) {
  return v < 0 ? u128(0) - u128(v) : u128(v);  // also for the most negative v
}

void set_mpz(mpz_ptr z, __int128 v) {
  const u128 m = magnitude(v);
  const mp_limb_t lo = mp_limb_t(m), hi = mp_limb_t(m >> 64);
  mp_limb_t* d = mpz_limbs_write(z, 2);  // z's storage, grown to two limbs if it has fewer
  d[0] = lo, d[1] = hi;
  const mp_size_t n = hi != 0 ? 2 : (lo != 0 ? 1 : 0);
  mpz_limbs_finish(z, v < 0 ? -n : n);
}

// Scratch integers for machine operands of GMP operations: they keep their storage, so a view
// costs no allocation after the first few.
struct Scratch {
  mpz_class a, b;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

}  // namespace

Int::Int(const mpz_class& z) : big_(true) {
  mpz_init_set(&z_, z.get_mpz_t());
  shrink();
}

Int::Int(const Int& o) : big_(o.big_) {
  if (big_)
    mpz_init_set(&z_, &o.z_);
  else
    small_ = o.small_;
}

Int::Int(Int&& o) noexcept : big_(o.big_) {
  if (big_)
    z_ = o.z_, o.big_ = false, o.small_ = 0;  // the limbs change owner
  else
    small_ = o.small_;
}

Int& Int::operator=(const Int& o) {
  if (this == &o) return *this;
  if (o.big_)
    mpz_set(make_big(), &o.z_);  // reuses this one's limbs
  else
    set(o.small_);  // keeps this one's GMP storage, if any
  return *this;
}

Int& Int::operator=(Int&& o) noexcept {
  if (this == &o) return *this;
  if (big_) mpz_clear(&z_);
  big_ = o.big_;
  if (big_)
    z_ = o.z_, o.big_ = false, o.small_ = 0;
  else
    small_ = o.small_;
  return *this;
}

Int::~Int() {
  if (big_) mpz_clear(&z_);
}

mpz_ptr Int::make_big() {
  if (!big_) {
    const __int128 v = small_;
    mpz_init(&z_);
    big_ = true;
    set_mpz(&z_, v);
  }
  return &z_;
}

void Int::set(__int128 v) {
  if (big_)
    set_mpz(&z_, v);
  else
    small_ = v;
}

void Int::shrink() {
  if (!big_ || mpz_sizeinbase(&z_, 2) > 126) return;
  const u128 m = (u128(mpz_getlimbn(&z_, 1)) << 64) | u128(mpz_getlimbn(&z_, 0));
  const bool negative = mpz_sgn(&z_) < 0;
  mpz_clear(&z_);
  big_ = false;
  small_ = negative ? -__int128(m) : __int128(m);
}

mpz_srcptr Int::view(const Int& x, mpz_ptr scratch) {
  if (x.big_) return &x.z_;
  set_mpz(scratch, x.small_);
  return scratch;
}

mpz_class Int::to_mpz() const {
  mpz_class z;
  if (big_)
    mpz_set(z.get_mpz_t(), &z_);
  else
    set_mpz(z.get_mpz_t(), small_);
  return z;
}

double Int::frexp(long* e) const {
  if (big_) return mpz_get_d_2exp(e, &z_);
  const u128 m = magnitude(small_);
  if (m == 0) return *e = 0, 0.0;
  const std::uint64_t hi = std::uint64_t(m >> 64), lo = std::uint64_t(m);
  const int bits = hi ? 128 - __builtin_clzll(hi) : 64 - __builtin_clzll(lo);
  const int drop = bits > 53 ? bits - 53 : 0;  // truncate to 53 bits: exact as a double
  const double t = std::ldexp(double(std::uint64_t(m >> drop)), drop - bits);
  *e = bits;
  return small_ < 0 ? -t : t;
}

// The machine result if `machine` reports no overflow, else GMP's.
template <class Machine, class Gmp>
Int Int::binary(const Int& a, const Int& b, Machine machine, Gmp gmp) {
  __int128 r;
  if (!a.big_ && !b.big_ && !machine(a.small_, b.small_, &r)) return of(r);
  Int out;
  mpz_srcptr x = view(a, scratch().a.get_mpz_t()), y = view(b, scratch().b.get_mpz_t());
  gmp(out.make_big(), x, y);
  out.shrink();
  return out;
}

Int operator+(const Int& a, const Int& b) {
  return Int::binary(
      a, b, [](__int128 x, __int128 y, __int128* r) { return __builtin_add_overflow(x, y, r); },
      mpz_add);
}

Int operator-(const Int& a, const Int& b) {
  return Int::binary(
      a, b, [](__int128 x, __int128 y, __int128* r) { return __builtin_sub_overflow(x, y, r); },
      mpz_sub);
}

Int operator*(const Int& a, const Int& b) {
  return Int::binary(
      a, b, [](__int128 x, __int128 y, __int128* r) { return __builtin_mul_overflow(x, y, r); },
      mpz_mul);
}

Int operator<<(const Int& a, unsigned long k) {
  Int out;
  mul_2exp(out, a, k);
  return out;
}

Int gcd(const Int& a, const Int& b) {
  const auto machine = [](__int128 x, __int128 y, __int128* r) {
    u128 u = magnitude(x), v = magnitude(y);  // Euclid on magnitudes: no overflow
    while (v != 0) u = std::exchange(v, u % v);
    *r = __int128(u);
    return u >> 126 != 0;  // 2^127 (both the most negative value, or one and 0) does not fit
  };
  return Int::binary(a, b, machine, mpz_gcd);
}

Int divexact(const Int& a, const Int& b) {
  const auto machine = [](__int128 x, __int128 y, __int128* r) {
    if (y == -1 && x < -(__int128(1) << 126)) return true;  // the one overflowing quotient
    *r = x / y;
    return false;
  };
  return Int::binary(a, b, machine, mpz_divexact);
}

int compare(const Int& a, const Int& b) {
  if (!a.big_ && !b.big_) return (a.small_ > b.small_) - (a.small_ < b.small_);
  const int c =
      mpz_cmp(Int::view(a, scratch().a.get_mpz_t()), Int::view(b, scratch().b.get_mpz_t()));
  return (c > 0) - (c < 0);
}

int compare_abs(const Int& a, const Int& b) {
  if (!a.big_ && !b.big_) {
    const u128 x = magnitude(a.small_), y = magnitude(b.small_);
    return (x > y) - (x < y);
  }
  const int c =
      mpz_cmpabs(Int::view(a, scratch().a.get_mpz_t()), Int::view(b, scratch().b.get_mpz_t()));
  return (c > 0) - (c < 0);
}

void mul(Int& r, const Int& a, const Int& b) {
  __int128 p;
  if (!a.big_ && !b.big_ && !__builtin_mul_overflow(a.small_, b.small_, &p)) return r.set(p);
  mpz_srcptr x = Int::view(a, scratch().a.get_mpz_t()), y = Int::view(b, scratch().b.get_mpz_t());
  mpz_mul(r.make_big(), x, y);  // the views first: r may be a or b
}

void mul_2exp(Int& r, const Int& a, unsigned long k) {
  if (!a.big_) {
    const u128 m = magnitude(a.small_);
    if (m == 0) return r.set(0);
    if (k < 126 && (m >> (126 - k)) == 0) {
      const __int128 s = __int128(m << k);
      return r.set(a.small_ < 0 ? -s : s);
    }
  }
  mpz_srcptr x = Int::view(a, scratch().a.get_mpz_t());
  mpz_mul_2exp(r.make_big(), x, k);
}

// In place: r keeps its GMP form once it has one (sums of products only grow).
void Int::accumulate(Int& r, const Int& a, const Int& b, bool subtract) {
  __int128 p, s;
  if (!r.big_ && !a.big_ && !b.big_ && !__builtin_mul_overflow(a.small_, b.small_, &p) &&
      !(subtract ? __builtin_sub_overflow(r.small_, p, &s)
                 : __builtin_add_overflow(r.small_, p, &s))) {
    r.small_ = s;
    return;
  }
  mpz_srcptr x = view(a, scratch().a.get_mpz_t()), y = view(b, scratch().b.get_mpz_t());
  (subtract ? mpz_submul : mpz_addmul)(r.make_big(), x, y);
}

void addmul(Int& r, const Int& a, const Int& b) {
  Int::accumulate(r, a, b, false);
}

void submul(Int& r, const Int& a, const Int& b) {
  Int::accumulate(r, a, b, true);
}

}  // namespace fdh::exact::algebra

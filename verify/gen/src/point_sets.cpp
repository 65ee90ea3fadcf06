#include "fdh/gen/point_sets.hpp"

#include <cmath>
#include <random>

#include "fdh/dyadic.hpp"
#include "fdh/kdop.hpp"

namespace fdh::verify {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int integer(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// A double with all 53 bits in use, of magnitude about 2^e, either sign.
double full_bits(Rng& rng, int e) {
  const double m = uniform(rng, 1, 2) + std::ldexp(double(rng() >> 11), -52);
  return std::ldexp(integer(rng, 0, 1) ? m : -m, e);
}

Vec3 random_vec(Rng& rng, double r) {
  return {uniform(rng, -r, r), uniform(rng, -r, r), uniform(rng, -r, r)};
}

// q with d·q = d·p exactly, q != p where an exact step is found: a step t with d·t = 0 on two
// coordinates, a multiple of both coordinates' ulps, at most about r. Else p itself.
Vec3 step_along_plane(Rng& rng, const Vec3& p, const Direction& d, double r) {
  const int dd[3] = {d.x, d.y, d.z};
  int i = 0;
  while (dd[i] == 0) ++i;
  int j = (i + 1) % 3;
  for (int c = 0; c < 3; ++c)
    if (c != i && dd[c] != 0) j = c;
  const double pi = p[i], pj = p[j];
  const int e = std::max(std::ilogb(pi), std::ilogb(pj)) - 52;
  const int spare = std::max(0, std::ilogb(r) - 21 - e);
  for (int attempt = 0; attempt < 16; ++attempt) {
    const double delta = std::ldexp(double(integer(rng, 1, 1 << 20)), e + integer(rng, 0, spare));
    // d_i t_i + d_j t_j = 0: t_i = delta d_i, t_j = -delta d_j (an axis d leaves j free).
    const double ti = dd[j] ? delta * dd[i] : 0, tj = dd[j] ? -delta * dd[j] : delta;
    double qi, qj;
    if (!add_exactly(pi, ti, qi) || !add_exactly(pj, tj, qj)) continue;
    double q[3] = {p.x, p.y, p.z};
    q[i] = qi, q[j] = qj;
    return {q[0], q[1], q[2]};
  }
  return p;
}

// p plus 0 to 3 points on the side of the plane through p where d·x is below (side -1) or above
// it, spread over r along the plane.
std::vector<Vec3> one_side(Rng& rng, const Vec3& p, const Direction& d, int side, double r) {
  const Vec3 dv{double(d.x), double(d.y), double(d.z)};
  const double len2 = dot(dv, dv);
  std::vector<Vec3> set = {p};
  for (int n = integer(rng, 0, 3); n > 0; --n) {
    const Vec3 u = random_vec(rng, r);
    const double off = side * uniform(rng, 0.25, 1) * r;  // d·(p + s) - d·p ~ off
    set.push_back(p + (u + ((off - dot(dv, u)) / len2) * dv));
  }
  return set;
}

}  // namespace

std::vector<Vec3> random_point_set(std::uint64_t seed) {
  Rng rng(seed);
  const int e = integer(rng, -8, 20);
  const Vec3 centre{full_bits(rng, e), full_bits(rng, e), full_bits(rng, e)};
  const double r = std::ldexp(1.0, e - integer(rng, 0, 30));
  std::vector<Vec3> pts;
  for (int n = integer(rng, 1, 8); n > 0; --n) pts.push_back(centre + random_vec(rng, r));
  return pts;
}

TouchingSets touching_point_sets(std::uint64_t seed) {
  Rng rng(seed);
  Direction d = kDirections[std::size_t(integer(rng, 0, 12))];
  if (integer(rng, 0, 1)) d = {-d.x, -d.y, -d.z};
  const int e = integer(rng, -8, 20);
  const Vec3 p{full_bits(rng, e), full_bits(rng, e), full_bits(rng, e)};
  const bool shared = integer(rng, 0, 3) == 0;
  const double r = std::ldexp(1.0, e - integer(rng, 0, 30));
  const Vec3 q = shared ? p : step_along_plane(rng, p, d, r);
  TouchingSets t{one_side(rng, p, d, -1, r), one_side(rng, q, d, +1, r), ""};
  t.contact = q == p ? "shared point"
                     : "plane (" + std::to_string(d.x) + "," + std::to_string(d.y) + "," +
                           std::to_string(d.z) + ")";
  return t;
}

}  // namespace fdh::verify

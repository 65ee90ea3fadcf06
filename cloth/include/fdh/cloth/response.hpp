// The collision response of Han & Jia 2013 §4, for a particle that hit a still surface with
// unit outward normal n. The paper writes k_f for two different coefficients; they are kept
// apart here:
//   v_n = (v·n)·n,  v_t = v - v_n
//   eq. (4), restitution:  v'  = v_t - restitution·v_n
//   eq. (5), friction:     v'' = v' - friction·|v_n|·v'/|v'|
// Eq. (5) as printed would reverse v' when friction·|v_n| > |v'|; friction stops the particle
// there instead (v'' = 0), as Coulomb friction does. A particle already leaving the surface
// (v·n >= 0) keeps its velocity.
#pragma once

#include "fdh/vec3.hpp"

namespace fdh::cloth {

struct ResponseCoefficients {
  double restitution = 0.1;  // eq. (4): 0 = inelastic, 1 = elastic
  double friction = 0.3;     // eq. (5)
};

inline Vec3 respond(const Vec3& v, const Vec3& n, const ResponseCoefficients& c) {
  const double vn = dot(v, n);
  if (vn >= 0) return v;
  const Vec3 v_n = vn * n;
  const Vec3 v1 = (v - v_n) - c.restitution * v_n;  // eq. (4)
  const double speed = norm(v1);
  const double slow = c.friction * -vn;  // friction·|v_n|
  if (slow >= speed) return Vec3{};
  return (1 - slow / speed) * v1;  // eq. (5): v' - slow·v'/|v'|
}

}  // namespace fdh::cloth

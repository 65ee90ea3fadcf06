// The points of a moving query at a time t, as the CCD filters (ccd_robust.cpp,
// ccd_robust_delta.cpp) evaluate them: each point moves linearly from x0 (t = 0) to x1 (t = 1).
// Private to fast/.
#pragma once

#include "fdh/interval.hpp"
#include "fdh/vec3.hpp"

namespace fdh::motion {

// A point of the motion at a time t: an Interval (rigorous bounds over a time interval) or a
// double (a plain estimate at one instant, for the cheap looks that only choose to give up).
template <class T>
struct V3 {
  T x, y, z;
};
template <class T>
V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
V3<T> operator*(const T& s, const V3<T>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline Interval lerp(double x0, double x1, const Interval& t) {
  const Interval a = Interval::point(x0);
  return a + t * (Interval::point(x1) - a);
}
inline double lerp(double x0, double x1, double t) {
  return x0 + t * (x1 - x0);
}
template <class T>
V3<T> at(const Vec3& x0, const Vec3& x1, const T& t) {
  return {lerp(x0.x, x1.x, t), lerp(x0.y, x1.y, t), lerp(x0.z, x1.z, t)};
}

}  // namespace fdh::motion

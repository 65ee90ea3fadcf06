// A plain 3-vector of doubles. Every operation is one IEEE operation per component, so the
// error bounds in the filters can count roundings exactly.
#pragma once

#include <cmath>

namespace fdh {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
  friend bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator-(const Vec3& a) {
  return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline Vec3& operator+=(Vec3& a, const Vec3& b) {
  return a = a + b;
}
inline Vec3& operator-=(Vec3& a, const Vec3& b) {
  return a = a - b;
}

inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
// Plain comparisons: std::fmax must order NaNs and costs a call in a hot loop.
inline double max_abs(const Vec3& a) {
  const double x = std::fabs(a.x), y = std::fabs(a.y), z = std::fabs(a.z);
  const double xy = x > y ? x : y;
  return xy > z ? xy : z;
}

}  // namespace fdh

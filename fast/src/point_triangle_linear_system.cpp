#include "fdh/point_triangle/linear_system.hpp"

#include <Eigen/Dense>

namespace fdh {

bool linear_system(const Vec3& b0, const Vec3& b1, const Vec3& d, const Vec3& e, const Vec3& f) {
  const auto col = [](const Vec3& v) { return Eigen::Vector3d(v.x, v.y, v.z); };
  Eigen::Matrix3d m;  // t(B'-B) - u(E-D) - v(F-D) = D - B
  m.col(0) = col(b1 - b0);
  m.col(1) = col(d - e);
  m.col(2) = col(d - f);
  if (m.determinant() == 0) return false;
  const Eigen::Vector3d x = m.inverse() * col(d - b0);  // 3×3 inverse: cofactors (Cramer)
  const double t = x[0], u = x[1], v = x[2];
  return t >= 0 && t <= 1 && u >= 0 && v >= 0 && u + v <= 1;
}

}  // namespace fdh

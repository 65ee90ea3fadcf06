#include "fdh/cloth/scene.hpp"

namespace fdh::cloth {

TriMesh obstacle_mesh(const Obstacle& o, double grow) {
  if (o.kind == Obstacle::Kind::Sphere) return sphere_mesh(o.centre, o.r + grow, o.level);
  const Vec3 g = {grow, grow, grow};
  return box_mesh(o.lo - g, o.hi + g);
}

double Scene::skin() const {
  if (thickness >= 0) return thickness;
  return 0.6 * cloth.size / (cloth.grid - 1);
}

}  // namespace fdh::cloth

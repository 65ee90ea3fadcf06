#include "fdh/cloth/scene.hpp"

#include <algorithm>
#include <cmath>

namespace fdh::cloth {

TriMesh obstacle_mesh(const Obstacle& o, double grow) {
  if (o.kind == Obstacle::Kind::Sphere) return sphere_mesh(o.centre, o.r + grow, o.level);
  const Vec3 g = {grow, grow, grow};
  return box_mesh(o.lo - g, o.hi + g);
}

// Box: the distance to the nearest face inside, to the nearest point outside (Quilez's
// signed distance of a box, by the offsets from its centre).
double obstacle_distance(const Obstacle& o, const Vec3& p) {
  if (o.kind == Obstacle::Kind::Sphere) return norm(p - o.centre) - o.r;
  const Vec3 c = 0.5 * (o.lo + o.hi), h = 0.5 * (o.hi - o.lo), d = p - c;
  const Vec3 q = {std::abs(d.x) - h.x, std::abs(d.y) - h.y, std::abs(d.z) - h.z};
  const Vec3 out = {std::max(q.x, 0.0), std::max(q.y, 0.0), std::max(q.z, 0.0)};
  return norm(out) + std::min(std::max({q.x, q.y, q.z}), 0.0);
}

double Scene::skin() const {
  if (thickness >= 0) return thickness;
  return 0.6 * cloth.size / (cloth.grid - 1);
}

double Scene::self_gap() const {
  return self_distance >= 0 ? self_distance : skin();
}

}  // namespace fdh::cloth

#include "fdh/cloth/obstacle_mesh.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace fdh::cloth {

TriMesh box_mesh(const Vec3& lo, const Vec3& hi) {
  TriMesh m;
  for (int i = 0; i < 8; ++i)  // bit 0: x, bit 1: y, bit 2: z
    m.x.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  // Each face as a quad a b c d, counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                           {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                           {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  for (const auto& f : faces) {
    m.tris.push_back({f[0], f[1], f[2]});
    m.tris.push_back({f[0], f[2], f[3]});
  }
  return m;
}

TriMesh sphere_mesh(const Vec3& centre, double r, int level) {
  const double g = (1 + std::sqrt(5.0)) / 2;  // the golden ratio: icosahedron corners
  std::vector<Vec3> unit = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                            {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                            {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const auto normalize = [](const Vec3& p) { return (1 / norm(p)) * p; };
  for (Vec3& p : unit) p = normalize(p);
  std::vector<Tri> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {  // split every triangle in four, midpoints pushed out
    std::map<std::pair<int, int>, int> mid;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      unit.push_back(normalize(unit[a] + unit[b]));
      return mid[key] = int(unit.size()) - 1;
    };
    std::vector<Tri> next;
    for (const Tri& t : tris) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }
  TriMesh m;
  for (const Vec3& p : unit) m.x.push_back(centre + r * p);
  m.tris = std::move(tris);
  return m;
}

}  // namespace fdh::cloth

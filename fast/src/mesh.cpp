#include "fdh/mesh.hpp"

namespace fdh {

void TriMesh::append(const TriMesh& other) {
  const int base = int(x.size());
  x.insert(x.end(), other.x.begin(), other.x.end());
  for (const Tri& t : other.tris) tris.push_back({t[0] + base, t[1] + base, t[2] + base});
}

Vec3 unit_normal(const TriMesh& m, int t) {
  const Vec3& a = m.x[m.tris[t][0]];
  const Vec3 n = cross(m.x[m.tris[t][1]] - a, m.x[m.tris[t][2]] - a);
  return (1 / norm(n)) * n;
}

}  // namespace fdh

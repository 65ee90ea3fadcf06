// Bullet's axis-aligned boxes, in Debian's double-precision build (bullet-float64: btScalar is
// double): btDbvtAabbMm::FromPoints (the broad phase's tree boxes: per-axis min and max), and the
// AABB that shapes report through getAabb with the identity transform: btConvexHullShape with
// margin 0 and btBvhTriangleMeshShape over a fan of the points. A shape's getAabb goes through a
// centre and a half extent (btTransformAabb in LinearMath/btAabbUtil2.h, btTriangleMeshShape),
// which rounds. Overlap: Intersect for btDbvtAabbMm, TestAabbAgainstAabb2 for shapes'.
#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <LinearMath/btAabbUtil2.h>
#include <LinearMath/btScalar.h>

#include <vector>

#include "fdh/peers/peers.hpp"

namespace fdh::verify {
namespace {

static_assert(sizeof(btScalar) == sizeof(double), "the peers use Bullet in double precision");

const std::vector<Direction> kAxes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

btVector3 bt(const Vec3& p) {
  return btVector3(p.x, p.y, p.z);
}

void store(const btVector3& mn, const btVector3& mx, double* lo, double* hi) {
  for (int a = 0; a < 3; ++a) lo[a] = mn[a], hi[a] = mx[a];
}

BoxMethod aabb_method(std::string name, std::string summary) {
  BoxMethod m;
  m.name = std::move(name);
  m.summary = std::move(summary);
  m.k = 6;
  m.directions = kAxes;
  m.promise = Promise::None;
  m.overlap = [](const double* la, const double* ha, const double* lb, const double* hb) {
    return TestAabbAgainstAabb2(btVector3(la[0], la[1], la[2]), btVector3(ha[0], ha[1], ha[2]),
                                btVector3(lb[0], lb[1], lb[2]), btVector3(hb[0], hb[1], hb[2]));
  };
  return m;
}

BoxMethod dbvt_from_points() {
  BoxMethod m = aabb_method("dbvt-from-points", "btDbvtAabbMm::FromPoints, Intersect");
  m.build = [](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    std::vector<btVector3> p;
    for (std::size_t i = 0; i < n; ++i) p.push_back(bt(pts[i]));
    const btDbvtAabbMm box = btDbvtAabbMm::FromPoints(p.data(), int(n));
    store(box.Mins(), box.Maxs(), lo, hi);
  };
  m.overlap = [](const double* la, const double* ha, const double* lb, const double* hb) {
    const auto box = [](const double* lo, const double* hi) {
      return btDbvtAabbMm::FromMM(btVector3(lo[0], lo[1], lo[2]), btVector3(hi[0], hi[1], hi[2]));
    };
    return Intersect(box(la, ha), box(lb, hb));
  };
  return m;
}

BoxMethod convex_hull_aabb() {
  BoxMethod m = aabb_method("convex-hull-aabb", "btConvexHullShape, margin 0, getAabb");
  m.build = [](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    btConvexHullShape hull;
    for (std::size_t i = 0; i < n; ++i) hull.addPoint(bt(pts[i]), false);
    hull.setMargin(0);
    hull.recalcLocalAabb();
    btVector3 mn, mx;
    hull.getAabb(btTransform::getIdentity(), mn, mx);
    store(mn, mx, lo, hi);
  };
  return m;
}

// The points as a triangle fan (0, i, i + 1); one or two points make one degenerate triangle.
BoxMethod bvh_triangle_mesh_aabb() {
  BoxMethod m = aabb_method("bvh-trimesh-aabb", "btBvhTriangleMeshShape of a fan, getAabb");
  m.build = [](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    btTriangleMesh mesh;  // 32-bit indices, 4-component (btScalar) vertices: no float copy
    if (n < 3) mesh.addTriangle(bt(pts[0]), bt(pts[n - 1]), bt(pts[n - 1]));
    for (std::size_t i = 1; i + 1 < n; ++i)
      mesh.addTriangle(bt(pts[0]), bt(pts[i]), bt(pts[i + 1]));
    const btBvhTriangleMeshShape shape(&mesh, true);
    btVector3 mn, mx;
    shape.getAabb(btTransform::getIdentity(), mn, mx);
    store(mn, mx, lo, hi);
  };
  return m;
}

}  // namespace

PeerLibrary bullet_library() {
  return {"bullet",
          std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100),
          "double",
          {dbvt_from_points(), convex_hull_aabb(), bvh_triangle_mesh_aabb()}};
}

}  // namespace fdh::verify

// Bullet 3.24 (Debian's libbullet-dev, double precision), btDbvt::collideTT on the same cloth
// and table as ours: one leaf per particle holding its swept box (start and end of the step),
// as our cloth tree holds; one leaf per table triangle. Both trees are built by insertion, then
// optimised top down (Bullet's best static build).
#include <benchmark/benchmark.h>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include "cloth_on_table.hpp"

namespace fdh::bench {
namespace {

btVector3 bt(const Vec3& v) {
  return btVector3(v.x, v.y, v.z);
}

struct CountPairs : btDbvt::ICollide {
  long pairs = 0;
  void Process(const btDbvtNode*, const btDbvtNode*) override { ++pairs; }
};

void bullet_collideTT(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  btDbvt cloth, table;
  for (std::size_t i = 0; i < c.x0.size(); ++i) {
    const btVector3 p[2] = {bt(c.x0[i]), bt(c.x1[i])};
    cloth.insert(btDbvtVolume::FromPoints(p, 2), nullptr);
  }
  for (const Tri& t : c.table.tris) {
    const btVector3 p[3] = {bt(c.table.x[t[0]]), bt(c.table.x[t[1]]), bt(c.table.x[t[2]])};
    table.insert(btDbvtVolume::FromPoints(p, 3), nullptr);
  }
  cloth.optimizeTopDown();
  table.optimizeTopDown();
  long pairs = 0;
  for (auto _ : state) {
    CountPairs count;
    cloth.collideTT(cloth.m_root, table.m_root, count);
    pairs = count.pairs;
  }
  state.counters["pairs"] = double(pairs);
}

BENCHMARK(bullet_collideTT)->Arg(25)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fdh::bench

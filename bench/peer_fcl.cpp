// FCL 0.7 (Debian's libfcl-dev), BVHModel<KDOP<double, 18>>, on the same cloth and table as
// ours. FCL's trees hold triangles at one position (it has no swept leaves), so its cloth model
// is the cloth's triangles at the end of the step.
//   fcl_refit:   new vertex positions, then FCL's bottom-up refit of the whole tree;
//   fcl_collide: the cloth model against the table model, every contact pair enumerated (FCL's
//                collide always runs its triangle-triangle narrow phase).
#include <benchmark/benchmark.h>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <memory>

#include "cloth_on_table.hpp"

namespace fdh::bench {
namespace {

using Model = fcl::BVHModel<fcl::KDOP<double, 18>>;

std::vector<fcl::Vector3d> to_fcl(const std::vector<Vec3>& x) {
  std::vector<fcl::Vector3d> p;
  p.reserve(x.size());
  for (const Vec3& v : x) p.emplace_back(v.x, v.y, v.z);
  return p;
}

std::shared_ptr<Model> model_of(const std::vector<Vec3>& x, const std::vector<Tri>& tris) {
  std::vector<fcl::Triangle> t;
  t.reserve(tris.size());
  for (const Tri& f : tris) t.emplace_back(f[0], f[1], f[2]);
  auto m = std::make_shared<Model>();
  m->beginModel();
  m->addSubModel(to_fcl(x), t);
  m->endModel();
  return m;
}

void fcl_refit(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  const auto model = model_of(c.x0, c.cloth_tris);
  const std::vector<fcl::Vector3d> x1 = to_fcl(c.x1);
  for (auto _ : state) {
    model->beginUpdateModel();
    model->updateSubModel(x1);
    model->endUpdateModel(/*refit=*/true, /*bottomup=*/true);
    benchmark::DoNotOptimize(model->getBV(0).bv);
  }
}

void fcl_collide(benchmark::State& state) {
  const ClothOnTable& c = cloth_on_table(int(state.range(0)));
  const fcl::CollisionObjectd cloth(model_of(c.x1, c.cloth_tris));
  const fcl::CollisionObjectd table(model_of(c.table.x, c.table.tris));
  fcl::CollisionRequestd request(/*num_max_contacts=*/100000000, /*enable_contact=*/false);
  std::size_t contacts = 0;
  for (auto _ : state) {
    fcl::CollisionResultd result;
    fcl::collide(&cloth, &table, request, result);
    contacts = result.numContacts();
  }
  state.counters["contacts"] = double(contacts);
}

BENCHMARK(fcl_refit)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(fcl_collide)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fdh::bench

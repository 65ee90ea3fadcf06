// The FDH tree's k: build, refit and traversal time against the candidate pairs it leaves.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {
namespace {

struct Mesh {
  std::vector<Vec3> x;
  std::vector<Tri> tris;
};

// A UV sphere of radius 1 at the origin.
Mesh sphere(int rings, int sectors) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      const double th = pi * r / rings, ph = 2 * pi * s / sectors;
      m.x.push_back({std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      const int a = r * sectors + s, b = r * sectors + (s + 1) % sectors;
      const int c = a + sectors, d = b + sectors;
      m.tris.push_back({a, c, b});
      m.tris.push_back({b, c, d});
    }
  return m;
}

// An n×n cloth over [-1.5, 1.5]^2 resting just above the sphere (or at the equator's height),
// and the same cloth one step later, moved down by 0.01.
Mesh cloth(int n, std::vector<Vec3>& later) {
  Mesh m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -1.5 + 3.0 * i / (n - 1), z = -1.5 + 3.0 * j / (n - 1);
      const double r2 = x * x + z * z;
      m.x.push_back({x, r2 < 1 ? std::sqrt(1 - r2) + 0.005 : 0.005 - 0.2 * (r2 - 1), z});
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      m.tris.push_back({a, c, b});
      m.tris.push_back({b, c, d});
    }
  later = m.x;
  for (Vec3& p : later) p.y -= 0.01;
  return m;
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

template <int K>
KdopTreeRow measure(int grid) {
  const Mesh obstacle = sphere(24, 48);
  std::vector<Vec3> later;
  const Mesh c = cloth(grid, later);
  const Bvh<K> table(obstacle.tris, obstacle.x);
  const int first = most_aligned_slab<K>(Vec3{0, -1, 0});
  const int reps = 20;
  std::vector<double> build, refit, trav;
  std::size_t pairs = 0;
  for (int r = 0; r < reps; ++r) {
    auto t = std::chrono::steady_clock::now();
    Bvh<K> tree(c.tris, c.x, later);
    build.push_back(ms_since(t));
    t = std::chrono::steady_clock::now();
    tree.refit(c.x, later);
    refit.push_back(ms_since(t));
    std::vector<std::pair<int, int>> out;
    t = std::chrono::steady_clock::now();
    traverse(tree, table, out, first);
    trav.push_back(ms_since(t));
    pairs = out.size();
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  return {K,
          grid,
          long(c.tris.size()),
          long(obstacle.tris.size()),
          median(build),
          median(refit),
          median(trav),
          long(pairs)};
}

}  // namespace

std::vector<KdopTreeRow> kdop_tree(int grid) {
  return {measure<6>(grid), measure<14>(grid), measure<18>(grid), measure<26>(grid)};
}

std::string kdop_tree_csv(const std::vector<KdopTreeRow>& rows) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "k,grid,cloth_triangles,obstacle_triangles,build_ms,refit_ms,traverse_ms,"
                 "candidate_pairs\n");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const KdopTreeRow& r = rows[i];
    if (i > 0 && r.grid != rows[i - 1].grid) fmt::format_to(to, "\n");
    fmt::format_to(to, "{},{},{},{},{:.6g},{:.6g},{:.6g},{}\n", r.k, r.grid, r.cloth_triangles,
                   r.obstacle_triangles, r.build_ms, r.refit_ms, r.traverse_ms, r.candidate_pairs);
  }
  return fmt::to_string(out);
}

}  // namespace fdh::verify

#include "fdh/cloth/patch_tree.hpp"

#include <algorithm>

namespace fdh::cloth {

PatchTree::PatchTree(const Cloth& cloth) : cloth_(cloth), grid_(cloth.grid()), cols_(grid_ - 1) {
  nodes_.reserve(2 * std::size_t(cols_) * cols_);
  build(0, 0, cols_, cols_);
  own_primitives();
  normals_.resize(nodes_.size());
  order_ = BottomUp(nodes_);
  lean_.resize(nodes_.size());
}

int PatchTree::build(int r0, int c0, int r1, int c1) {
  const int id = int(nodes_.size());
  nodes_.push_back({r0, c0, r1, c1});
  if (r1 - r0 == 1 && c1 - c0 == 1) return id;
  int left, right;
  if (r1 - r0 >= c1 - c0) {
    const int rm = (r0 + r1) / 2;
    left = build(r0, c0, rm, c1);
    right = build(rm, c0, r1, c1);
  } else {
    const int cm = (c0 + c1) / 2;
    left = build(r0, c0, r1, cm);
    right = build(r0, cm, r1, c1);
  }
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

// A particle (r, c), or an edge whose lower end is (r, c), belongs to the cell
// (min(r, cols - 1), min(c, cols - 1)): a cell whose corners hold all its particles.
void PatchTree::own_primitives() {
  const int cells = cols_ * cols_;
  const auto owner = [&](int particle) {
    const int r = particle / grid_, c = particle % grid_;
    return std::min(r, cols_ - 1) * cols_ + std::min(c, cols_ - 1);
  };
  const auto fill = [&](const std::vector<int>& of, std::vector<int>& items,
                        std::vector<int>& start) {
    start.assign(cells + 1, 0);
    for (const int c : of) ++start[c + 1];
    for (int c = 0; c < cells; ++c) start[c + 1] += start[c];
    items.resize(of.size());
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int i = 0; i < int(of.size()); ++i) items[next[of[i]]++] = i;
  };
  std::vector<int> of(cloth_.n());
  for (int i = 0; i < cloth_.n(); ++i) of[i] = owner(i);
  fill(of, vertex_, vertex_start_);
  const auto& edges = cloth_.edges();
  of.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) of[e] = owner(std::min(edges[e][0], edges[e][1]));
  fill(of, edge_, edge_start_);
}

void PatchTree::update_normals(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  const auto& tris = cloth_.triangles();
  bottom_up([&](int i) {
    const Node& n = nodes_[i];
    if (!n.leaf()) {
      normals_[i] = merge(normals_[n.left], normals_[n.right]);
      lean_[i] = lean_[n.left] + lean_[n.right];
      return;
    }
    const auto [s, t] = triangles(cell_of(n));
    const auto swept = [&](const Tri& f) {
      return swept_normals(x0[f[1]] - x0[f[0]], x1[f[1]] - x1[f[0]], x0[f[2]] - x0[f[0]],
                           x1[f[2]] - x1[f[0]]);
    };
    normals_[i] = merge(swept(tris[s]), swept(tris[t]));
    lean_[i] = normals_[i].lo + normals_[i].hi;  // a direction inside the box, to aim at
  });
}

// The boundary's particles in the triangles' winding order (counter-clockwise seen from their
// normals at rest): down the first column, along the last row, up the last column, back along
// the first row.
void PatchTree::contour_of(const Node& n, std::vector<int>& out) const {
  out.clear();
  const auto at = [&](int r, int c) { return r * grid_ + c; };
  for (int r = n.r0; r < n.r1; ++r) out.push_back(at(r, n.c0));
  for (int c = n.c0; c < n.c1; ++c) out.push_back(at(n.r1, c));
  for (int r = n.r1; r > n.r0; --r) out.push_back(at(r, n.c1));
  for (int c = n.c1; c > n.c0; --c) out.push_back(at(n.r0, c));
}

bool PatchTree::flat(int node, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) const {
  const int bit = best_direction(positive_directions(normals_[node]), lean_[node]);
  if (bit < 0) return false;
  const Node& n = nodes_[node];
  // The centre: the middle of the patch's middle cell, moving with it.
  const int rm = (n.r0 + n.r1 - 1) / 2, cm = (n.c0 + n.c1 - 1) / 2;
  const int a = rm * grid_ + cm, b = a + 1, c = a + grid_, d = c + 1;
  const Vec3 m0 = 0.25 * (x0[a] + x0[b] + x0[c] + x0[d]);
  const Vec3 m1 = 0.25 * (x1[a] + x1[b] + x1[c] + x1[d]);
  thread_local std::vector<int> contour;
  contour_of(n, contour);
  return contour_is_star_shaped(contour, x0, x1, m0, m1, bit);
}

}  // namespace fdh::cloth

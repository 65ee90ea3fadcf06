#include "inside_count.hpp"

#include <algorithm>
#include <numeric>

namespace fdh::audit {
namespace {

int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
}

}  // namespace

// Connected pieces by union-find over the triangles' vertices, in order of first vertex.
InsideCount::InsideCount(const std::vector<Tri>& obstacle) {
  int vertices = 0;
  for (const Tri& t : obstacle) vertices = std::max({vertices, t[0] + 1, t[1] + 1, t[2] + 1});
  std::vector<int> parent(vertices);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Tri& t : obstacle)
    for (int c = 1; c < 3; ++c) parent[root(parent, t[c])] = root(parent, t[0]);
  std::vector<int> piece_of_root(vertices, -1), local(vertices, -1);
  const auto piece = [&](int v) -> Piece& {
    int& p = piece_of_root[root(parent, v)];
    if (p < 0) p = int(pieces_.size()), pieces_.emplace_back();
    return pieces_[p];
  };
  for (const Tri& t : obstacle) {
    Piece& p = piece(t[0]);
    Tri r;
    for (int c = 0; c < 3; ++c) {
      if (local[t[c]] < 0) local[t[c]] = int(p.vertices.size()), p.vertices.push_back(t[c]);
      r[c] = local[t[c]];
    }
    p.tris.push_back(r);
  }
}

void InsideCount::build(const std::vector<Vec3>& y) {
  std::vector<int> keep;  // the closed pieces: topology decides, so the first build does
  if (!built_)
    for (int p = 0; p < int(pieces_.size()); ++p) keep.push_back(p);
  else
    for (const Closed& c : closed_) keep.push_back(c.piece);
  closed_.clear();
  for (const int p : keep) {
    TriMesh m;
    m.tris = pieces_[p].tris;
    for (const int v : pieces_[p].vertices) m.x.push_back(y[v]);
    if (!built_ && !exact::is_closed_manifold(m)) continue;
    Vec3 lo = m.x.front(), hi = lo;
    for (const Vec3& q : m.x) {
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
      hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    }
    closed_.push_back({p, lo, hi, exact::ClosedMesh(m)});
  }
  built_for_ = y;
  built_ = true;
}

long InsideCount::count(const std::vector<Vec3>& x, const std::vector<int>& vertices,
                        const std::vector<Vec3>& y) {
  if (pieces_.empty()) return 0;
  if (!built_ || y != built_for_) build(y);
  long n = 0;
  for (const int v : vertices)
    for (const Closed& c : closed_)
      if (in_box(x[v], c.lo, c.hi) && c.mesh.strictly_inside(x[v])) {
        ++n;
        break;
      }
  return n;
}

}  // namespace fdh::audit

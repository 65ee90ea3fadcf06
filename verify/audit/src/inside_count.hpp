// The audit's `inside` count: cloth particles strictly inside a closed obstacle
// (fdh/exact/inside.hpp). The obstacles' triangles are split into connected pieces (triangles
// sharing a vertex); each piece that is a closed manifold mesh has an inside, an open piece
// (a sheet, a plane) has none and is not counted against. A particle inside several pieces
// counts once. A box test first: a point strictly inside a piece is inside its vertices' box.
#pragma once

#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/exact/inside.hpp"
#include "fdh/vec3.hpp"

namespace fdh::audit {

class InsideCount {
 public:
  // The obstacles' triangles (indices checked by mesh_parts before).
  explicit InsideCount(const std::vector<Tri>& obstacle);

  // How many of the cloth's `vertices` are strictly inside a closed piece, the obstacles at
  // positions `y` (the pieces are rebuilt only when y changes: still obstacles pay once).
  long count(const std::vector<Vec3>& x, const std::vector<int>& vertices,
             const std::vector<Vec3>& y);

  int closed_pieces() const { return int(closed_.size()); }

 private:
  struct Piece {
    std::vector<int> vertices;  // obstacle vertex indices, in order
    std::vector<Tri> tris;      // renumbered into `vertices`
  };
  struct Closed {
    int piece;
    Vec3 lo, hi;  // the box of its vertices
    exact::ClosedMesh mesh;
  };
  void build(const std::vector<Vec3>& y);

  std::vector<Piece> pieces_;
  std::vector<Closed> closed_;
  std::vector<Vec3> built_for_;  // the positions closed_ holds
  bool built_ = false;
};

}  // namespace fdh::audit

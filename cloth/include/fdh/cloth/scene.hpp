// A scene: one cloth, its still obstacles, the step and the collision coefficients. Read from
// the text files in corpus/scenes/ (docs/formats.md); every field has a default, so a scene
// states only what it uses.
#pragma once

#include <string>
#include <vector>

#include "fdh/cloth/cloth.hpp"
#include "fdh/cloth/obstacle_mesh.hpp"
#include "fdh/cloth/response.hpp"

namespace fdh::cloth {

// A closed obstacle. A table is a top and four legs, each a box.
struct Obstacle {
  enum class Kind { Box, Sphere } kind = Kind::Box;
  Vec3 lo, hi;  // a box
  Vec3 centre;  // a sphere
  double r = 0;
  int level = 3;  // a sphere's subdivision (20·4^level triangles)
};

// The obstacle as a closed triangle mesh, grown outward by `grow` (a box's faces move out, a
// sphere's radius grows).
TriMesh obstacle_mesh(const Obstacle& o, double grow = 0);

// The signed distance from p to the obstacle's solid (negative inside), in floating point: to
// the sphere itself, not its triangles, and to the box. A cheap measure of the gap a run keeps
// (scene runs report its smallest value), never a collision test.
double obstacle_distance(const Obstacle& o, const Vec3& p);

struct Scene {
  std::string name;
  ClothSpec cloth;
  std::vector<Obstacle> obstacles;
  double dt = 1e-3;  // s per step; one step per frame
  int frames = 1000;
  ResponseCoefficients response;
  // The collision skin, m: particles are kept outside the obstacles grown by this much.
  // Negative = automatic, 0.6 × the particle spacing (docs/methods.md, "Cloth": why a point-only
  // test needs it).
  double thickness = -1;
  // The cloth against itself (fdh/cloth/self_collision.hpp), after the obstacle response.
  bool self_collision = false;
  // The gap the self-collision pass keeps between the cloth's own primitives, m: a pair stops
  // where its distance reaches it (0: at contact). Negative = automatic, the skin.
  double self_distance = -1;
  // A checked run (verify's run_scene) checks every audit_every-th frame and the last: the
  // narrow phase against the exact test and the exact audit. A large cloth's checks cost far
  // more than its frames.
  int audit_every = 1;

  double skin() const;      // the thickness in use, m
  double self_gap() const;  // the self distance in use, m
};

}  // namespace fdh::cloth

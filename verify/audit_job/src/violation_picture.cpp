#include "violation_picture.hpp"

#include "fdh/io/scene_output.hpp"

namespace fdh::verify {
namespace {

const std::array<double, 3> kClothColour = {0.85, 0.25, 0.2}, kObstacleColour = {0.7, 0.7, 0.65},
                            kMarkColour = {0.15, 0.45, 1.0}, kNearColour = {1.0, 0.8, 0.1};

// The triangles of `tris` holding every vertex of `vs` (an edge's two, or a vertex's one).
void mark_holding(const std::vector<Tri>& tris, std::vector<int> vs, std::vector<Tri>& out) {
  for (const Tri& t : tris) {
    int held = 0;
    for (const int v : vs) held += t[0] == v || t[1] == v || t[2] == v;
    if (held == int(vs.size())) out.push_back(t);
  }
}

// The violation's triangles, the cloth's and the obstacles'.
std::pair<std::vector<Tri>, std::vector<Tri>> marked(const audit::Violation& v,
                                                     const audit::Topology& t) {
  std::vector<Tri> c, o;
  const auto& x = v.vertices;
  using K = audit::ViolationKind;
  switch (audit::contact_kind(v.kind)) {  // a proximity kind marks the same primitives
    case K::SelfIntersection:
      c = {t.cloth[std::size_t(v.triangles[0])], t.cloth[std::size_t(v.triangles[1])]};
      break;
    case K::ObstacleIntersection:
      c = {t.cloth[std::size_t(v.triangles[0])]}, o = {t.obstacle[std::size_t(v.triangles[1])]};
      break;
    case K::SelfVertexFace:
      mark_holding(t.cloth, {x[0]}, c), c.push_back({x[1], x[2], x[3]});
      break;
    case K::SelfEdgeEdge:
      mark_holding(t.cloth, {x[0], x[1]}, c), mark_holding(t.cloth, {x[2], x[3]}, c);
      break;
    case K::ClothVertexObstacle:
      mark_holding(t.cloth, {x[0]}, c), o.push_back({x[1], x[2], x[3]});
      break;
    case K::ObstacleVertexCloth:
      mark_holding(t.obstacle, {x[0]}, o), c.push_back({x[1], x[2], x[3]});
      break;
    case K::ClothEdgeObstacleEdge:
      mark_holding(t.cloth, {x[0], x[1]}, c), mark_holding(t.obstacle, {x[2], x[3]}, o);
      break;
    default:
      break;
  }
  return {c, o};
}

}  // namespace

std::string violation_picture(const std::vector<Vec3>& cloth, const std::vector<Vec3>& obstacle,
                              const audit::Violation& v, const audit::Topology& t) {
  const auto [mc, mo] = marked(v, t);
  // Proximity in yellow, intersection in blue.
  const std::array<double, 3>& mark = audit::is_proximity(v.kind) ? kNearColour : kMarkColour;
  // The marks first: the renderer keeps the first of two triangles at the same depth.
  std::vector<SceneMesh> meshes = {{"marked", &cloth, &mc, mark},
                                   {"marked obstacle", &obstacle, &mo, mark},
                                   {"cloth", &cloth, &t.cloth, kClothColour},
                                   {"obstacles", &obstacle, &t.obstacle, kObstacleColour}};
  return encode_png(render(meshes, 800, 600, frame_view({meshes[2], meshes[3]})));
}

}  // namespace fdh::verify

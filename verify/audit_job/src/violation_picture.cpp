#include "violation_picture.hpp"

#include <algorithm>
#include <cmath>

#include "fdh/io/scene_output.hpp"

namespace fdh::verify {
namespace {

const std::array<double, 3> kClothColour = {0.85, 0.25, 0.2}, kObstacleColour = {0.7, 0.7, 0.65},
                            kMarkColour = {0.15, 0.45, 1.0}, kNearColour = {1.0, 0.8, 0.1},
                            kObstacleMarkColour = {0.95, 0.7, 0.15};

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

// Positions turned so that axis `up` points along +y, the renderer's up (a rotation, so the
// picture is not mirrored).
std::vector<Vec3> turned(const std::vector<Vec3>& x, int up) {
  std::vector<Vec3> out;
  out.reserve(x.size());
  for (const Vec3& p : x)
    out.push_back(up == 2 ? Vec3{p.x, p.z, -p.y} : up == 0 ? Vec3{-p.y, p.x, p.z} : p);
  return out;
}

// The close-up: the sphere around the marked cloth triangles (every kind has some), widened so
// that they fill about half of the picture and their neighbourhood shows around them (the
// triangles within 1.6 times its radius: near_ball).
Framing close_up(const std::vector<Vec3>& x, const std::vector<Tri>& marks) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Tri& t : marks)
    for (const int i : t) {
      const Vec3& p = x[std::size_t(i)];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return {0.5 * (lo + hi), std::max(0.55 * norm(hi - lo), 1e-9)};
}

// The triangles of `tris` whose box meets the ball: what a close-up draws, so that nothing far
// from the violation (the far side of a sphere, a fold above) stands between it and the eye.
std::vector<Tri> near_ball(const std::vector<Vec3>& x, const std::vector<Tri>& tris,
                           const Framing& ball) {
  std::vector<Tri> out;
  const Vec3& c = ball.centre;
  for (const Tri& t : tris) {
    double d2 = 0;
    for (double Vec3::*axis : {&Vec3::x, &Vec3::y, &Vec3::z}) {
      double lo = INFINITY, hi = -INFINITY;
      for (const int i : t) {
        lo = std::min(lo, x[std::size_t(i)].*axis), hi = std::max(hi, x[std::size_t(i)].*axis);
      }
      const double d = std::max({lo - c.*axis, c.*axis - hi, 0.0});
      d2 += d * d;
    }
    if (d2 <= ball.radius * ball.radius) out.push_back(t);
  }
  return out;
}

// The close-up's direction: of eight, from above first (front-right, front-left, back-right,
// back-left) then from below, the one that sees the most of the marks (depth-tested in a small
// probe picture, the marks in a colour of their own).
Framing best_view(const std::vector<SceneMesh>& scene, const std::vector<SceneMesh>& marks,
                  Framing view) {
  const Vec3 dirs[8] = {{0.55, 0.45, 1},  {-0.55, 0.45, 1},  {0.55, 0.45, -1},  {-0.55, 0.45, -1},
                        {0.55, -0.45, 1}, {-0.55, -0.45, 1}, {0.55, -0.45, -1}, {-0.55, -0.45, -1}};
  std::vector<SceneMesh> probe;
  for (SceneMesh m : marks) probe.push_back((m.colour = {0, 0, 1}, m));
  probe.insert(probe.end(), scene.begin(), scene.end());
  long best = -1;
  Vec3 chosen = dirs[0];
  for (const Vec3& d : dirs) {
    view.towards_eye = d;
    const Picture pic = render(probe, 160, 120, view);
    long seen = 0;
    for (std::size_t i = 0; i < pic.rgb.size(); i += 3)
      seen += pic.rgb[i] == 0 && pic.rgb[i + 1] == 0 && pic.rgb[i + 2] > 0;
    if (seen > best) best = seen, chosen = d;
  }
  view.towards_eye = chosen;
  return view;
}

// The scene rendered with the marks drawn over it, hidden or not: the pixels where the marks
// alone differ from the bare background.
Picture with_marks(const std::vector<SceneMesh>& scene, const std::vector<SceneMesh>& marks,
                   int width, int height, const Framing& view) {
  Picture pic = render(scene, width, height, view);
  const Picture bare = render({}, width, height, view), only = render(marks, width, height, view);
  for (std::size_t i = 0; i < pic.rgb.size(); i += 3)
    if (only.rgb[i] != bare.rgb[i] || only.rgb[i + 1] != bare.rgb[i + 1] ||
        only.rgb[i + 2] != bare.rgb[i + 2])
      for (std::size_t k = 0; k < 3; ++k) pic.rgb[i + k] = only.rgb[i + k];
  return pic;
}

// `inset` into the top right corner of `pic`, in a dark frame.
void paste(Picture& pic, const Picture& inset) {
  const int x0 = pic.width - inset.width - 8, y0 = 8;
  for (int y = -2; y < inset.height + 2; ++y)
    for (int x = -2; x < inset.width + 2; ++x) {
      const bool border = x < 0 || y < 0 || x >= inset.width || y >= inset.height;
      const std::size_t to =
          (std::size_t(y0 + y) * std::size_t(pic.width) + std::size_t(x0 + x)) * 3;
      for (std::size_t k = 0; k < 3; ++k)
        pic.rgb[to + k] =
            border
                ? 60
                : inset.rgb[(std::size_t(y) * std::size_t(inset.width) + std::size_t(x)) * 3 + k];
    }
}

Vec3 centroid(const std::vector<Vec3>& x) {
  Vec3 c{0, 0, 0};
  for (const Vec3& p : x) c = c + p;
  return x.empty() ? c : (1.0 / double(x.size())) * c;
}

}  // namespace

int up_axis_of(const std::vector<Vec3>& start, const std::vector<Vec3>& now,
               const std::vector<Vec3>& obstacle) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto* xs : {&now, &obstacle})
    for (const Vec3& p : *xs) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  const Vec3 d = centroid(now) - centroid(start), size = hi - lo;
  const double m[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
  const int moved = int(std::max_element(m, m + 3) - m);
  if (m[moved] > 1e-3 * norm(size)) return moved;  // fell: gravity points down the up axis
  const double e[3] = {size.x, size.y, size.z};
  return int(std::min_element(e, e + 3) - e);
}

std::string violation_picture(const std::vector<Vec3>& cloth_x, const std::vector<Vec3>& obstacle_x,
                              const audit::Violation& v, const audit::Topology& t, int up) {
  const auto [mc, mo] = marked(v, t);
  const std::vector<Vec3> cloth = turned(cloth_x, up), obstacle = turned(obstacle_x, up);
  // The obstacle's marks first (the renderer keeps the first of two triangles at the same
  // depth); the cloth's drawn over everything: an obstacle's mark may be a ground that fills the
  // picture, a cloth's is small.
  const std::vector<SceneMesh> scene = {{"marked obstacle", &obstacle, &mo, kObstacleMarkColour},
                                        {"cloth", &cloth, &t.cloth, kClothColour},
                                        {"obstacles", &obstacle, &t.obstacle, kObstacleColour}};
  // Proximity in yellow, intersection in blue.
  const std::array<double, 3>& mark = audit::is_proximity(v.kind) ? kNearColour : kMarkColour;
  const std::vector<SceneMesh> marks = {{"marked", &cloth, &mc, mark}};
  const Framing view = close_up(cloth, mc);
  const Framing ball{view.centre, 2 * view.radius};
  const std::vector<Tri> nc = near_ball(cloth, t.cloth, ball),
                         no = near_ball(obstacle, t.obstacle, ball);
  const std::vector<SceneMesh> near = {scene[0],
                                       {"cloth", &cloth, &nc, kClothColour},
                                       {"obstacles", &obstacle, &no, kObstacleColour}};
  Picture pic = with_marks(near, marks, 800, 600, best_view(near, marks, view));
  paste(pic, with_marks(scene, marks, 240, 180, frame_view({scene[1], scene[2]})));
  return encode_png(pic);
}

}  // namespace fdh::verify

#include "fdh/io/scene_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <vector>

#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

using cloth::Obstacle;
using cloth::Scene;

// The ranges of docs/limits.md ("Scene values"): wide enough for any cloth on a human scale,
// narrow enough that a run stays finite (no inf or nan reaches an output).
struct Range {
  double lo, hi;
  bool open_lo;  // lo itself excluded
  const char* unit;
};
constexpr Range kCoordinate = {-1e3, 1e3, false, "m"};
constexpr Range kSize = {1e-3, 1e3, false, "m"};
constexpr Range kRadius = {1e-4, 1e3, false, "m"};
constexpr Range kMass = {1e-6, 1e6, false, "kg"};
constexpr Range kStructural = {0, 1e9, true, "N/m"};
constexpr Range kSpring = {0, 1e9, false, "N/m"};
constexpr Range kDamping = {0, 1e3, false, "1/s"};
constexpr Range kGravity = {-1e3, 1e3, false, "m/s^2"};
constexpr Range kWind = {-1e3, 1e3, false, "m/s"};
constexpr Range kUnit = {0, 1, false, ""};
constexpr Range kDt = {1e-9, 1, false, "s"};
constexpr Range kFriction = {0, 1e3, false, ""};
constexpr Range kThickness = {0, 1e3, false, "m"};
constexpr double kMinBoxSide = 1e-4;  // m
constexpr double kMinStep = 1e-9;     // s, the least step a run takes
constexpr long kMaxFrames = 100000000;
constexpr int kMaxSphereLevel = 6;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool in_range(const Range& r, double v) {
  return (r.open_lo ? v > r.lo : v >= r.lo) && v <= r.hi;
}

std::string range_text(const Range& r) {
  return (r.open_lo ? "(" : "[") + num(r.lo) + ", " + num(r.hi) + "]" +
         (*r.unit ? std::string(" ") + r.unit : "");
}

long sphere_triangles(int level) {
  return 20L << (2 * level);
}

// One line's values, read with the file and line at hand for errors.
class Line {
 public:
  Line(const std::string& path, long line, std::string key, std::vector<std::string> words)
      : path_(path), line_(line), key_(std::move(key)), words_(std::move(words)) {}

  void expect(std::size_t lo, std::size_t hi) const {
    if (words_.size() < lo || words_.size() > hi)
      fail("'" + key_ + "' takes " +
           (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
           " value" + (hi == 1 ? "" : "s") + ", not " + std::to_string(words_.size()));
  }
  std::size_t size() const { return words_.size(); }
  const std::string& word(std::size_t i) const { return words_[i]; }
  double number(std::size_t i) const {
    std::string why;
    const auto v = parse_double(words_[i], why);
    if (!v) fail(key_ + ": " + why);
    return *v;
  }
  // Value i, named `field` in a message, within `r`.
  double ranged(std::size_t i, const std::string& field, const Range& r) const {
    const double v = number(i);
    if (!in_range(r, v)) fail(field + " must be in " + range_text(r) + ", not " + quote(words_[i]));
    return v;
  }
  long integer(std::size_t i, long lo, long hi, const std::string& raise = "") const {
    const double v = number(i);
    if (v != std::floor(v) || v < lo || v > hi)
      fail(key_ + " must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
           "], not " + quote(words_[i]) + (v > hi && !raise.empty() ? "; " + raise : ""));
    return long(v);
  }
  Vec3 vec(std::size_t i, const Range& r) const {
    return {ranged(i, key_ + " x", r), ranged(i + 1, key_ + " y", r),
            ranged(i + 2, key_ + " z", r)};
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

 private:
  const std::string& path_;
  long line_;
  std::string key_;
  std::vector<std::string> words_;
};

using Reader = std::function<void(const Line&, Scene&)>;

// One entry per keyword of the format, with its range: a table, longer than a function should
// be because it is data (docs/formats.md lists the same keywords, docs/limits.md the ranges).
const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> r = {
      {"name",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         for (const char ch : l.word(0))
           if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
             l.fail("name " + quote(l.word(0)) + " holds a control byte");
         s.name = l.word(0);
       }},
      {"grid",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         const long max = long(bound_value(kMaxGrid));
         s.cloth.grid = int(l.integer(0, 2, max, bound_text(kMaxGrid, max)));
       }},
      {"size",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.size = l.ranged(0, "size", kSize); }},
      {"centre",
       [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.centre = l.vec(0, kCoordinate); }},
      {"mass",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.mass = l.ranged(0, "mass", kMass); }},
      {"stiffness",
       [](const Line& l, Scene& s) {
         l.expect(3, 3);
         s.cloth.k_structural = l.ranged(0, "stiffness structural", kStructural);
         s.cloth.k_shear = l.ranged(1, "stiffness shear", kSpring);
         s.cloth.k_bend = l.ranged(2, "stiffness bend", kSpring);
       }},
      {"damping",
       [](const Line& l, Scene& s) {
         l.expect(1, 1), s.cloth.damping = l.ranged(0, "damping", kDamping);
       }},
      {"gravity",
       [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.gravity = l.vec(0, kGravity); }},
      {"wind", [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.wind = l.vec(0, kWind); }},
      {"pin",
       [](const Line& l, Scene& s) {
         l.expect(2, 2);
         s.cloth.pins.push_back({l.ranged(0, "pin u", kUnit), l.ranged(1, "pin v", kUnit)});
       }},
      {"box",
       [](const Line& l, Scene& s) {
         l.expect(6, 6);
         Obstacle o;
         o.lo = l.vec(0, kCoordinate), o.hi = l.vec(3, kCoordinate);
         if (!(o.lo.x < o.hi.x && o.lo.y < o.hi.y && o.lo.z < o.hi.z))
           l.fail("box: the first corner must be below the second on every axis");
         const Vec3 side = o.hi - o.lo;
         if (side.x < kMinBoxSide || side.y < kMinBoxSide || side.z < kMinBoxSide)
           l.fail("box: every side must be at least " + num(kMinBoxSide) + " m");
         s.obstacles.push_back(o);
       }},
      {"sphere",
       [](const Line& l, Scene& s) {
         l.expect(4, 5);
         Obstacle o;
         o.kind = Obstacle::Kind::Sphere;
         o.centre = l.vec(0, kCoordinate);
         o.r = l.ranged(3, "sphere radius", kRadius);
         if (l.size() == 5) o.level = int(l.integer(4, 0, kMaxSphereLevel));
         s.obstacles.push_back(o);
       }},
      {"dt", [](const Line& l, Scene& s) { l.expect(1, 1), s.dt = l.ranged(0, "dt", kDt); }},
      {"frames", [](const Line& l,
                    Scene& s) { l.expect(1, 1), s.frames = int(l.integer(0, 0, kMaxFrames)); }},
      {"restitution",
       [](const Line& l, Scene& s) {
         l.expect(1, 1), s.response.restitution = l.ranged(0, "restitution", kUnit);
       }},
      {"friction",
       [](const Line& l, Scene& s) {
         l.expect(1, 1), s.response.friction = l.ranged(0, "friction", kFriction);
       }},
      {"audit_every",
       [](const Line& l, Scene& s) {
         l.expect(1, 1), s.audit_every = int(l.integer(0, 1, kMaxFrames));
       }},
      {"self_collision",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         if (l.word(0) != "on" && l.word(0) != "off")
           l.fail("self_collision takes on or off, not " + quote(l.word(0)));
         s.self_collision = l.word(0) == "on";
       }},
      {"thickness",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         s.thickness = l.word(0) == "auto" ? -1 : l.ranged(0, "thickness", kThickness);
       }},
  };
  return r;
}

bool repeatable(const std::string& key) {
  return key == "pin" || key == "box" || key == "sphere";
}

std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

long obstacle_triangles(const Scene& s) {
  long n = 0;
  for (const Obstacle& o : s.obstacles)
    n += o.kind == Obstacle::Kind::Sphere ? sphere_triangles(std::clamp(o.level, 0, 12)) : 12;
  return n;
}

// The whole scene against the ranges, the bounds and the rules that join two fields. `line_of`
// gives the line that set a keyword (0: a default, or a command-line override).
void check(const Scene& s, const std::string& path,
           const std::function<long(const std::string&)>& line_of) {
  const auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(path, line_of(key), what);
  };
  const auto range = [&](const std::string& key, const std::string& field, double v,
                         const Range& r) {
    if (!in_range(r, v)) fail(key, field + " must be in " + range_text(r) + ", not " + num(v));
  };
  const auto vec = [&](const std::string& key, const Vec3& v, const Range& r) {
    range(key, key + " x", v.x, r), range(key, key + " y", v.y, r), range(key, key + " z", v.z, r);
  };
  const cloth::ClothSpec& c = s.cloth;
  const long long max_grid = bound_value(kMaxGrid);
  if (c.grid < 2 || c.grid > max_grid)
    fail("grid", "grid must be a whole number in [2, " + std::to_string(max_grid) + "], not " +
                     std::to_string(c.grid) +
                     (c.grid > max_grid ? "; " + bound_text(kMaxGrid, max_grid) : ""));
  range("size", "size", c.size, kSize);
  vec("centre", c.centre, kCoordinate);
  range("mass", "mass", c.mass, kMass);
  range("stiffness", "stiffness structural", c.k_structural, kStructural);
  range("stiffness", "stiffness shear", c.k_shear, kSpring);
  range("stiffness", "stiffness bend", c.k_bend, kSpring);
  range("damping", "damping", c.damping, kDamping);
  vec("gravity", c.gravity, kGravity);
  vec("wind", c.wind, kWind);
  for (const auto& p : c.pins)
    range("pin", "pin u", p[0], kUnit), range("pin", "pin v", p[1], kUnit);
  for (const Obstacle& o : s.obstacles) {
    if (o.kind == Obstacle::Kind::Sphere) {
      vec("sphere", o.centre, kCoordinate);
      range("sphere", "sphere radius", o.r, kRadius);
      if (o.level < 0 || o.level > kMaxSphereLevel)
        fail("sphere", "sphere level must be in [0, 6], not " + std::to_string(o.level));
    } else {
      vec("box", o.lo, kCoordinate), vec("box", o.hi, kCoordinate);
      const Vec3 side = o.hi - o.lo;
      if (!(side.x >= kMinBoxSide && side.y >= kMinBoxSide && side.z >= kMinBoxSide))
        fail("box", "box: every side must be at least " + num(kMinBoxSide) + " m");
    }
  }
  const long long max_tris = bound_value(kMaxObstacleTriangles);
  const long tris = obstacle_triangles(s);
  if (tris > max_tris)
    fail(s.obstacles.back().kind == Obstacle::Kind::Sphere ? "sphere" : "box",
         "the obstacles have " + std::to_string(tris) + " triangles, more than " +
             std::to_string(max_tris) + "; " + bound_text(kMaxObstacleTriangles, max_tris));
  range("dt", "dt", s.dt, kDt);
  if (s.frames < 0 || s.frames > kMaxFrames)
    fail("frames",
         "frames must be a whole number in [0, 100000000], not " + std::to_string(s.frames));
  range("restitution", "restitution", s.response.restitution, kUnit);
  range("friction", "friction", s.response.friction, kFriction);
  if (s.thickness != -1) range("thickness", "thickness", s.thickness, kThickness);
  // Two fields together.
  if (c.damping * s.dt > 1)
    fail(line_of("damping") > line_of("dt") ? "damping" : "dt",
         "damping " + num(c.damping) + " 1/s times dt " + num(s.dt) +
             " s must be at most 1 (the air damping of one step would overshoot)");
  const double stable = cloth::stable_dt(c);
  if (s.dt > stable && 0.9 * stable < kMinStep)
    fail("stiffness", "the cloth's stable step is " + num(stable) + " s (stiffness " +
                          num(c.k_structural) + " N/m, mass " + num(c.mass) + " kg, grid " +
                          std::to_string(c.grid) + "), below the least step " + num(kMinStep) +
                          " s; lower the stiffness or the grid, "
                          "or raise the mass");
}

}  // namespace

void check_scene(const cloth::Scene& scene, const std::string& path) {
  check(scene, path, [](const std::string&) { return 0L; });
}

Scene read_scene(const std::string& path) {
  InputFile in(path);
  Scene scene;
  scene.name = stem(path);
  std::map<std::string, long> lines;  // the last line of each keyword
  long obstacle_tris = 0;
  const long long max_tris = bound_value(kMaxObstacleTriangles);
  std::string text;
  try {
    while (in.next(text)) {
      const long n = in.line();
      const std::size_t hash = text.find('#');
      if (hash != std::string::npos) text.erase(hash);
      std::istringstream is(text);
      std::string key, w;
      if (!(is >> key)) continue;
      std::vector<std::string> words;
      while (is >> w) words.push_back(w);
      if (key == "center") key = "centre";
      const auto it = readers().find(key);
      if (it == readers().end())
        throw InputError(path, n,
                         "unknown keyword " + quote(key) + " (see docs/formats.md, scenes)");
      if (!repeatable(key) && lines.count(key))
        throw InputError(path, n, "'" + key + "' given twice");
      lines[key] = n;
      const std::size_t obstacles = scene.obstacles.size();
      it->second(Line(path, n, key, std::move(words)), scene);
      if (scene.obstacles.size() > obstacles) {
        const Obstacle& o = scene.obstacles.back();
        obstacle_tris += o.kind == Obstacle::Kind::Sphere ? sphere_triangles(o.level) : 12;
        if (obstacle_tris > max_tris)
          throw InputError(path, n,
                           "the obstacles have " + std::to_string(obstacle_tris) +
                               " triangles, more than " + std::to_string(max_tris) + "; " +
                               bound_text(kMaxObstacleTriangles, max_tris));
      }
    }
  } catch (const std::bad_alloc&) {
    throw InputError(path, in.line(), "out of memory (docs/limits.md)");
  }
  check(scene, path, [&lines](const std::string& key) {
    const auto it = lines.find(key);
    return it == lines.end() ? 0L : it->second;
  });
  return scene;
}

}  // namespace fdh::verify

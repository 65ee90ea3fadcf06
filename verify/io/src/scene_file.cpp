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
#include "fdh/io/scene_schema.hpp"

namespace fdh::verify {
namespace {

using cloth::Obstacle;
using cloth::Scene;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

const char* const kComponent[3] = {" x", " y", " z"};

// A field's name in messages: a vector's component adds " x", " y" or " z".
std::string name_of(const SceneValue& f, int component) {
  return f.components == 3 ? std::string(f.field) + kComponent[component] : f.field;
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
  // Value i, named `name` in a message, within f's range.
  double ranged(std::size_t i, const std::string& name, const SceneValue& f) const {
    const double v = number(i);
    if (!f.admits(v)) fail(f.refusal(name, quote(words_[i]), v));
    return v;
  }
  // Value i, a whole number within f's range (named by the keyword, as the line shows it).
  long integer(std::size_t i, const SceneValue& f) const {
    const double v = number(i);
    if (!f.admits(v)) fail(f.refusal(key_, quote(words_[i]), v));
    return long(v);
  }
  Vec3 vec(std::size_t i, const SceneValue& f) const {
    return {ranged(i, name_of(f, 0), f), ranged(i + 1, name_of(f, 1), f),
            ranged(i + 2, name_of(f, 2), f)};
  }
  const std::string& key() const { return key_; }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

 private:
  const std::string& path_;
  long line_;
  std::string key_;
  std::vector<std::string> words_;
};

using Reader = std::function<void(const Line&, Scene&)>;

// A keyword whose fields the table reads alone: its values in table order, each in range.
void read_fields(const Line& l, Scene& s) {
  std::vector<const SceneValue*> fields;
  std::size_t n = 0;
  for (const SceneValue& f : scene_values())
    if (f.set && l.key() == f.keyword) fields.push_back(&f), n += std::size_t(f.components);
  l.expect(n, n);
  std::size_t i = 0;
  for (const SceneValue* f : fields)
    for (int c = 0; c < f->components; ++c, ++i)
      f->set(s, c, f->whole ? double(l.integer(i, *f)) : l.ranged(i, name_of(*f, c), *f));
}

void read_box(const Line& l, Scene& s) {
  l.expect(6, 6);
  Obstacle o;
  o.lo = l.vec(0, scene_value("box")), o.hi = l.vec(3, scene_value("box"));
  if (!(o.lo.x < o.hi.x && o.lo.y < o.hi.y && o.lo.z < o.hi.z))
    l.fail("box: the first corner must be below the second on every axis");
  const Vec3 side = o.hi - o.lo;
  const double min_side = scene_value("box side").lo;
  if (side.x < min_side || side.y < min_side || side.z < min_side)
    l.fail("box: every side must be at least " + num(min_side) + " m");
  s.obstacles.push_back(o);
}

void read_sphere(const Line& l, Scene& s) {
  l.expect(4, 5);
  Obstacle o;
  o.kind = Obstacle::Kind::Sphere;
  o.centre = l.vec(0, scene_value("sphere"));
  o.r = l.ranged(3, "sphere radius", scene_value("sphere radius"));
  if (l.size() == 5) o.level = int(l.integer(4, scene_value("sphere level")));
  s.obstacles.push_back(o);
}

void read_name(const Line& l, Scene& s) {
  l.expect(1, 1);
  for (const char ch : l.word(0))
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
      l.fail("name " + quote(l.word(0)) + " holds a control byte");
  s.name = l.word(0);
}

// Every keyword of the format: those of the schema's table (scene_schema.hpp) it reads alone,
// and those with rules of their own (docs/formats.md lists them all).
const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> r = [] {
    std::map<std::string, Reader> m = {
        {"name", read_name},
        {"box", read_box},
        {"sphere", read_sphere},
        {"pin",
         [](const Line& l, Scene& s) {
           l.expect(2, 2);
           s.cloth.pins.push_back({l.ranged(0, "pin u", scene_value("pin u")),
                                   l.ranged(1, "pin v", scene_value("pin v"))});
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
           s.thickness =
               l.word(0) == "auto" ? -1 : l.ranged(0, "thickness", scene_value("thickness"));
         }},
        {"self_distance",
         [](const Line& l, Scene& s) {
           l.expect(1, 1);
           s.self_distance = l.word(0) == "auto"
                                 ? -1
                                 : l.ranged(0, "self_distance", scene_value("self_distance"));
         }},
    };
    for (const SceneValue& f : scene_values())
      if (f.set) m.emplace(f.keyword, read_fields);
    return m;
  }();
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

using LineOf = std::function<long(const std::string&)>;

// f's value (component c) within its range, else an InputError at the line that set it.
void check_value(const SceneValue& f, int c, double v, const std::string& path,
                 const LineOf& line_of) {
  if (f.admits(v)) return;
  const std::string shown = f.whole ? std::to_string((long long)v) : num(v);
  throw InputError(path, line_of(f.keyword), f.refusal(name_of(f, c), shown, v));
}

// The obstacles: their fields' ranges, and their triangles within the bound.
void check_obstacles(const Scene& s, const std::string& path, const LineOf& line_of) {
  const auto range = [&](const char* field, int c, double v) {
    check_value(scene_value(field), c, v, path, line_of);
  };
  const auto vec = [&](const char* field, const Vec3& v) {
    for (int c = 0; c < 3; ++c) range(field, c, v[c]);
  };
  for (const auto& p : s.cloth.pins) range("pin u", 0, p[0]), range("pin v", 0, p[1]);
  for (const Obstacle& o : s.obstacles) {
    if (o.kind == Obstacle::Kind::Sphere) {
      vec("sphere", o.centre);
      range("sphere radius", 0, o.r);
      if (!scene_value("sphere level").admits(o.level))
        throw InputError(path, line_of("sphere"),
                         "sphere level must be in " + scene_value("sphere level").range_text() +
                             ", not " + std::to_string(o.level));
    } else {
      vec("box", o.lo), vec("box", o.hi);
      const Vec3 side = o.hi - o.lo;
      const double min_side = scene_value("box side").lo;
      if (!(side.x >= min_side && side.y >= min_side && side.z >= min_side))
        throw InputError(path, line_of("box"),
                         "box: every side must be at least " + num(min_side) + " m");
    }
  }
  const long long max_tris = bound_value(kMaxObstacleTriangles);
  const long tris = obstacle_triangles(s);
  if (tris > max_tris)
    throw InputError(
        path, line_of(s.obstacles.back().kind == Obstacle::Kind::Sphere ? "sphere" : "box"),
        "the obstacles have " + std::to_string(tris) + " triangles, more than " +
            std::to_string(max_tris) + "; " + bound_text(kMaxObstacleTriangles, max_tris));
}

// The whole scene against the ranges of the schema's table, the bounds and the rules that join
// two fields. `line_of` gives the line that set a keyword (0: a default, or a command-line
// override).
void check(const Scene& s, const std::string& path, const LineOf& line_of) {
  for (const SceneValue& f : scene_values())
    if (f.get)
      for (int c = 0; c < f.components; ++c) check_value(f, c, f.get(s, c), path, line_of);
  check_obstacles(s, path, line_of);
  if (s.thickness != -1) check_value(scene_value("thickness"), 0, s.thickness, path, line_of);
  if (s.self_distance != -1)
    check_value(scene_value("self_distance"), 0, s.self_distance, path, line_of);
  const auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(path, line_of(key), what);
  };
  const cloth::ClothSpec& c = s.cloth;
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

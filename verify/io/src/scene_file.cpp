#include "fdh/io/scene_file.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

using cloth::Obstacle;
using cloth::Scene;

// One line's values, read with the file and line at hand for errors.
class Line {
 public:
  Line(const std::string& path, int line, std::string key, std::vector<std::string> words)
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
  double at_least(std::size_t i, double lo, bool strict) const {
    const double v = number(i);
    if (strict ? !(v > lo) : !(v >= lo))
      fail(key_ + " must be " + (strict ? "> " : ">= ") + fmt(lo) + ", not " + words_[i]);
    return v;
  }
  double within(std::size_t i, double lo, double hi) const {
    const double v = number(i);
    if (v < lo || v > hi)
      fail(key_ + " must be in [" + fmt(lo) + ", " + fmt(hi) + "], not " + words_[i]);
    return v;
  }
  long integer(std::size_t i, long lo, long hi) const {
    const double v = number(i);
    if (v != std::floor(v) || v < lo || v > hi)
      fail(key_ + " must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
           "], not " + words_[i]);
    return long(v);
  }
  Vec3 vec(std::size_t i) const { return {number(i), number(i + 1), number(i + 2)}; }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

 private:
  static std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  const std::string& path_;
  int line_;
  std::string key_;
  std::vector<std::string> words_;
};

using Reader = std::function<void(const Line&, Scene&)>;

// One entry per keyword of the format, with its range: a table, longer than a function should
// be because it is data (docs/formats.md lists the same keywords).
const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> r = {
      {"name", [](const Line& l, Scene& s) { l.expect(1, 1), s.name = l.word(0); }},
      {"grid",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.grid = int(l.integer(0, 2, 4000)); }},
      {"size",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.size = l.at_least(0, 0, true); }},
      {"centre", [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.centre = l.vec(0); }},
      {"mass",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.mass = l.at_least(0, 0, true); }},
      {"stiffness",
       [](const Line& l, Scene& s) {
         l.expect(3, 3);
         s.cloth.k_structural = l.at_least(0, 0, true);
         s.cloth.k_shear = l.at_least(1, 0, false);
         s.cloth.k_bend = l.at_least(2, 0, false);
       }},
      {"damping",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.cloth.damping = l.at_least(0, 0, false); }},
      {"gravity", [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.gravity = l.vec(0); }},
      {"wind", [](const Line& l, Scene& s) { l.expect(3, 3), s.cloth.wind = l.vec(0); }},
      {"pin",
       [](const Line& l, Scene& s) {
         l.expect(2, 2);
         s.cloth.pins.push_back({l.within(0, 0, 1), l.within(1, 0, 1)});
       }},
      {"box",
       [](const Line& l, Scene& s) {
         l.expect(6, 6);
         Obstacle o;
         o.lo = l.vec(0), o.hi = l.vec(3);
         if (!(o.lo.x < o.hi.x && o.lo.y < o.hi.y && o.lo.z < o.hi.z))
           l.fail("box: the first corner must be below the second on every axis");
         s.obstacles.push_back(o);
       }},
      {"sphere",
       [](const Line& l, Scene& s) {
         l.expect(4, 5);
         Obstacle o;
         o.kind = Obstacle::Kind::Sphere;
         o.centre = l.vec(0);
         o.r = l.at_least(3, 0, true);
         if (l.size() == 5) o.level = int(l.integer(4, 0, 6));
         s.obstacles.push_back(o);
       }},
      {"dt", [](const Line& l, Scene& s) { l.expect(1, 1), s.dt = l.at_least(0, 0, true); }},
      {"frames",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.frames = int(l.integer(0, 0, 100000000)); }},
      {"restitution",
       [](const Line& l, Scene& s) { l.expect(1, 1), s.response.restitution = l.within(0, 0, 1); }},
      {"friction", [](const Line& l,
                      Scene& s) { l.expect(1, 1), s.response.friction = l.at_least(0, 0, false); }},
      {"self_collision",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         if (l.word(0) != "on" && l.word(0) != "off")
           l.fail("self_collision takes on or off, not '" + l.word(0) + "'");
         s.self_collision = l.word(0) == "on";
       }},
      {"thickness",
       [](const Line& l, Scene& s) {
         l.expect(1, 1);
         s.thickness = l.word(0) == "auto" ? -1 : l.at_least(0, 0, false);
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

}  // namespace

Scene read_scene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  Scene scene;
  scene.name = stem(path);
  std::set<std::string> seen;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
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
      throw InputError(path, n, "unknown keyword '" + key + "' (see docs/formats.md, scenes)");
    if (!repeatable(key) && !seen.insert(key).second)
      throw InputError(path, n, "'" + key + "' given twice");
    it->second(Line(path, n, key, std::move(words)), scene);
  }
  if (in.bad()) throw InputError(path, 0, "read error");
  return scene;
}

}  // namespace fdh::verify

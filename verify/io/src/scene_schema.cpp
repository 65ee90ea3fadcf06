#include "fdh/io/scene_schema.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fdh::verify {
namespace {

using cloth::Scene;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string whole_text(double v) {
  return std::to_string((long long)v);
}

double& at(Vec3& v, int i) {
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

// A real in [lo, hi] (open at lo when `open`), a whole number, a vector, a field with no
// accessor: the table's rows in a few words.
SceneValue real(const char* key, const char* field, double lo, double hi, const char* unit,
                double (*get)(const Scene&, int), void (*set)(Scene&, int, double),
                bool open = false) {
  return {key, field, 1, false, lo, hi, open, unit, nullptr, get, set};
}
SceneValue whole(const char* key, double lo, double hi, const Bound* bound,
                 double (*get)(const Scene&, int), void (*set)(Scene&, int, double)) {
  return {key, key, 1, true, lo, hi, false, "", bound, get, set};
}
SceneValue vector(const char* key, double max, const char* unit,
                  double (*get)(const Scene&, int) = nullptr,
                  void (*set)(Scene&, int, double) = nullptr) {
  return {key, key, 3, false, -max, max, false, unit, nullptr, get, set};
}
SceneValue custom(const char* key, const char* field, bool is_whole, double lo, double hi,
                  const char* unit) {
  return {key, field, 1, is_whole, lo, hi, false, unit, nullptr, nullptr, nullptr};
}

#define FDH_FIELD(expr) \
  [](const Scene& s, int) { return double(s.expr); }, [](Scene& s, int, double v) { s.expr = v; }
#define FDH_WHOLE(expr, type)                         \
  [](const Scene& s, int) { return double(s.expr); }, \
      [](Scene& s, int, double v) { s.expr = type(v); }
#define FDH_VECTOR(expr)                           \
  [](const Scene& s, int i) { return s.expr[i]; }, \
      [](Scene& s, int i, double v) { at(s.expr, i) = v; }

std::vector<SceneValue> make_table() {
  return {
      whole("grid", kMinGrid, double(kMaxGrid.fallback), &kMaxGrid, FDH_WHOLE(cloth.grid, int)),
      real("size", "size", kMinSize, kMaxSize, "m", FDH_FIELD(cloth.size)),
      vector("centre", kMaxCoordinate, "m", FDH_VECTOR(cloth.centre)),
      real("mass", "mass", kMinMass, kMaxMass, "kg", FDH_FIELD(cloth.mass)),
      real("stiffness", "stiffness structural", 0, kMaxStiffness, "N/m",
           FDH_FIELD(cloth.k_structural), true),
      real("stiffness", "stiffness shear", 0, kMaxStiffness, "N/m", FDH_FIELD(cloth.k_shear)),
      real("stiffness", "stiffness bend", 0, kMaxStiffness, "N/m", FDH_FIELD(cloth.k_bend)),
      real("damping", "damping", 0, kMaxDamping, "1/s", FDH_FIELD(cloth.damping)),
      vector("gravity", kMaxGravity, "m/s^2", FDH_VECTOR(cloth.gravity)),
      vector("wind", kMaxWind, "m/s", FDH_VECTOR(cloth.wind)),
      custom("pin", "pin u", false, 0, 1, ""),
      custom("pin", "pin v", false, 0, 1, ""),
      vector("box", kMaxCoordinate, "m"),
      custom("box", "box side", false, kMinBoxSide, 2 * kMaxCoordinate, "m"),
      vector("sphere", kMaxCoordinate, "m"),
      custom("sphere", "sphere radius", false, kMinRadius, kMaxRadius, "m"),
      custom("sphere", "sphere level", true, 0, kMaxSphereLevel, ""),
      real("dt", "dt", kMinDt, kMaxDt, "s", FDH_FIELD(dt)),
      whole("frames", 0, double(kMaxFrames), nullptr, FDH_WHOLE(frames, int)),
      whole("audit_every", 1, double(kMaxFrames), nullptr, FDH_WHOLE(audit_every, int)),
      real("restitution", "restitution", 0, 1, "", FDH_FIELD(response.restitution)),
      real("friction", "friction", 0, kMaxFriction, "", FDH_FIELD(response.friction)),
      custom("thickness", "thickness", false, 0, kMaxThickness, "m"),
      custom("self_distance", "self_distance", false, 0, kMaxThickness, "m"),
  };
}

#undef FDH_FIELD
#undef FDH_WHOLE
#undef FDH_VECTOR

// "[lo, top]" or "(lo, top]", without the unit.
std::string range_up_to(const SceneValue& v, double top) {
  if (v.whole) return "[" + whole_text(v.lo) + ", " + whole_text(top) + "]";
  return (v.open_lo ? "(" : "[") + num(v.lo) + ", " + num(top) + "]";
}

}  // namespace

double SceneValue::max() const {
  return bound ? double(bound_value(*bound)) : hi;
}

bool SceneValue::admits(double v) const {
  const bool in_range = (open_lo ? v > lo : v >= lo) && v <= max();
  return in_range && (!whole || v == std::floor(v));
}

std::string SceneValue::range_text() const {
  const std::string unit_text = *unit ? std::string(" ") + unit : "";
  return range_up_to(*this, max()) + (whole ? "" : unit_text);
}

std::string SceneValue::refusal(const std::string& name, const std::string& value, double v) const {
  if (!whole) return name + " must be in " + range_text() + ", not " + value;
  const double top = max();
  return name + " must be a whole number in " + range_text() + ", not " + value +
         (bound && v > top ? "; " + bound_text(*bound, (long long)top) : "");
}

const std::vector<SceneValue>& scene_values() {
  static const std::vector<SceneValue> table = make_table();
  return table;
}

const SceneValue& scene_value(const std::string& field) {
  for (const SceneValue& v : scene_values())
    if (field == v.field) return v;
  throw std::logic_error("no scene value named " + field);
}

std::string scene_limits_markdown() {
  std::string out = "| keyword | field | range | unit |\n|---|---|---|---|\n";
  for (const SceneValue& v : scene_values()) {
    std::string field = v.field;
    if (v.components == 3) field += " x, y, z";
    std::string range = range_up_to(v, v.hi);  // the default, whatever the environment says
    if (v.bound) range += " (`" + std::string(v.bound->env) + "`)";
    if (v.whole) range += ", whole";
    out +=
        "| `" + std::string(v.keyword) + "` | " + field + " | " + range + " | " + v.unit + " |\n";
  }
  return out;
}

}  // namespace fdh::verify

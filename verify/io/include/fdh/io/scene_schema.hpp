// The scene format's values in one table: each keyword's fields with their ranges and units,
// wide enough for any cloth on a human scale, narrow enough that a run stays finite (no inf or
// nan reaches an output). The reader and the scene check (scene_file.hpp), simulate's overrides
// and docs/limits.md ("Scene values", compared with scene_limits_markdown() by a test) all take
// them from here.
#pragma once

#include <string>
#include <vector>

#include "fdh/cloth/scene.hpp"
#include "fdh/io/input_error.hpp"

namespace fdh::verify {

inline constexpr double kMaxCoordinate = 1e3;                 // m, each coordinate of a point
inline constexpr double kMinSize = 1e-3, kMaxSize = 1e3;      // m, the cloth's side
inline constexpr double kMinMass = 1e-6, kMaxMass = 1e6;      // kg, the cloth's
inline constexpr double kMaxStiffness = 1e9;                  // N/m
inline constexpr double kMaxDamping = 1e3;                    // 1/s
inline constexpr double kMaxGravity = 1e3;                    // m/s^2, each component
inline constexpr double kMaxWind = 1e3;                       // m/s, each component
inline constexpr double kMinRadius = 1e-4, kMaxRadius = 1e3;  // m, a sphere's
inline constexpr double kMinBoxSide = 1e-4;                   // m
inline constexpr int kMaxSphereLevel = 6;                     // 20·4^6 = 81920 triangles
inline constexpr double kMinDt = 1e-9, kMaxDt = 1;            // s
inline constexpr double kMinStep = 1e-9;                      // s, the least step a run takes
inline constexpr int kMinGrid = 2;                            // particles per side
inline constexpr long kMaxFrames = 100000000;                 // frames of a run, and audit_every
inline constexpr double kMaxFriction = 1e3;
inline constexpr double kMaxThickness = 1e3;  // m

// One field of a keyword. A scene line holds the values of its keyword's fields in table order.
struct SceneValue {
  const char* keyword;
  const char* field;   // as messages name it; a vector's components add " x", " y", " z"
  int components;      // 1, or 3 for a vector
  bool whole;          // a whole number
  double lo, hi;       // the range; a whole number's bounds
  bool open_lo;        // lo itself excluded
  const char* unit;    // "m", "N/m", ... or ""
  const Bound* bound;  // hi is this bound's value (an environment variable raises it), or null
  // The field of a scene, for keywords read and checked by the table alone (else null: the
  // repeated keywords pin, box and sphere, and thickness with its "auto").
  double (*get)(const cloth::Scene&, int component);
  void (*set)(cloth::Scene&, int component, double v);

  double max() const;  // hi, or the bound in force
  bool admits(double v) const;
  // "[0.001, 1000] m", "(0, 1e+09] N/m"
  std::string range_text() const;
  // "size must be in [0.001, 1000] m, not VALUE", or for a whole number "grid must be a whole
  // number in [2, 2000], not VALUE", with how to raise the bound when v is above it.
  std::string refusal(const std::string& name, const std::string& value, double v) const;
};

// Every field, in the order docs/limits.md lists them.
const std::vector<SceneValue>& scene_values();

// The field named `field` ("grid", "stiffness shear", "sphere level"); std::logic_error for an
// unknown name (a programming error).
const SceneValue& scene_value(const std::string& field);

// docs/limits.md's table of scene values, one row per field.
std::string scene_limits_markdown();

}  // namespace fdh::verify

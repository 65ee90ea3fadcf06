// The certificate's words on a minimum distance D (`audit --min-distance`): D, the rule on pairs
// near by construction and what it left out, and the nearest pairs the run looked at (the cloth
// against itself, and against the obstacles), each with its distance exactly (docs/audit.md,
// "Minimum distance").
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "fdh/audit_job/audit_report.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kClass[2] = {"self", "obstacle"};

// The classes the run has: self always, obstacle with obstacle triangles.
int classes(const AuditReport& r) {
  return r.topology().obstacle.empty() ? 1 : 2;
}

// The distance as its exact square where that is short (1/4096), else as its enclosure: the
// square of a distance between floats can have a hundred digits.
std::string nearest_text(const audit::Nearest& n) {
  const std::string exact = n.squared.size() <= 24
                                ? fmt::format("squared {} exactly", n.squared)
                                : fmt::format("in [{:.17g}, {:.17g}]", n.lo, n.hi);
  return fmt::format("{:.6g} ({}), frame {}, triangles {} and {}", n.lo, exact, n.frame,
                     n.triangles[0], n.triangles[1]);
}

}  // namespace

std::string nearest_words(const AuditReport& r) {
  const double d = r.options().min_distance;
  std::string out;
  for (int i = 0; i < classes(r); ++i)
    if (r.nearest(i).frame >= 0)
      out += fmt::format("; nearest {} {}", kClass[i], nearest_text(r.nearest(i)));
  if (out.empty()) return fmt::format("min distance {}: no pair came within reach of it", d);
  return fmt::format("min distance {}{}", d, out);
}

nlohmann::ordered_json proximity_json(const AuditReport& r) {
  const audit::Options& o = r.options();
  const audit::NearExcluded& e = r.totals().excluded;
  Json nearest = Json::object();
  for (int i = 0; i < 2; ++i) {
    const audit::Nearest& n = r.nearest(i);
    nearest[kClass[i]] = n.frame < 0 ? Json(nullptr)
                                     : Json{{"frame", n.frame},
                                            {"triangles", n.triangles},
                                            {"squared", n.squared},
                                            {"distance_lo", n.lo},
                                            {"distance_hi", n.hi}};
  }
  return {{"min_distance", o.min_distance},
          {"near_rule", {{"rings", o.near_rings}, {"first_frame", o.near_first_frame}}},
          {"excluded",
           {{"rings", e.rings},
            {"first_frame", e.first_frame},
            {"first_frame_pairs", e.first_frame_pairs}}},
          {"nearest", std::move(nearest)}};
}

std::string proximity_markdown(const AuditReport& r) {
  const audit::Options& o = r.options();
  const audit::NearExcluded& e = r.totals().excluded;
  std::string md = fmt::format(
      "Minimum distance D = {} (distance <= D counts). Pairs near by construction left out of "
      "the proximity kinds: cloth pairs within {} rings ({} tests){}.\n",
      o.min_distance, o.near_rings, e.rings,
      o.near_first_frame ? fmt::format(", pairs within D in the first frame ({} pairs, {} tests)",
                                       e.first_frame_pairs, e.first_frame)
                         : std::string());
  for (int i = 0; i < classes(r); ++i) {
    const audit::Nearest& n = r.nearest(i);
    md += n.frame < 0
              ? fmt::format("\nNearest {} pair: none came within reach of D.\n", kClass[i])
              : fmt::format(
                    "\nNearest {} pair: frame {}, triangles {} and {}, distance in "
                    "[{:.17g}, {:.17g}] (squared {}).\n",
                    kClass[i], n.frame, n.triangles[0], n.triangles[1], n.lo, n.hi, n.squared);
  }
  return md;
}

}  // namespace fdh::verify

// The certificate's words on a minimum distance D (`audit --min-distance`): D, the rule on pairs
// near by construction and what it left out, and the nearest pair the run looked at, with its
// distance exactly (docs/audit.md, "Minimum distance").
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "fdh/audit_job/audit_report.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

std::string nearest_place(const audit::Nearest& n) {
  return fmt::format("frame {}, {} triangles {} and {}", n.frame,
                     n.kind == audit::ViolationKind::SelfProximity ? "cloth" : "cloth and obstacle",
                     n.triangles[0], n.triangles[1]);
}

}  // namespace

std::string nearest_words(const AuditReport& r) {
  const audit::Nearest& n = r.nearest();
  const double d = r.options().min_distance;
  if (n.frame < 0) return fmt::format("min distance {}: no pair came within reach of it", d);
  return fmt::format("min distance {}: nearest {:.6g} (squared {} exactly), {}", d, n.lo, n.squared,
                     nearest_place(n));
}

nlohmann::ordered_json proximity_json(const AuditReport& r) {
  const audit::Options& o = r.options();
  const audit::NearExcluded& e = r.totals().excluded;
  const audit::Nearest& n = r.nearest();
  Json nearest = nullptr;
  if (n.frame >= 0)
    nearest = {{"frame", n.frame},         {"kind", audit::to_string(n.kind)},
               {"triangles", n.triangles}, {"squared", n.squared},
               {"distance_lo", n.lo},      {"distance_hi", n.hi}};
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
      "the proximity kinds: cloth pairs within {} rings ({} tests){}.\n\n",
      o.min_distance, o.near_rings, e.rings,
      o.near_first_frame ? fmt::format(", pairs within D in the first frame ({} pairs, {} tests)",
                                       e.first_frame_pairs, e.first_frame)
                         : std::string());
  const audit::Nearest& n = r.nearest();
  if (n.frame < 0) return md + "Nearest pair: none came within reach of D.\n";
  return md + fmt::format("Nearest pair: {}, distance in [{:.17g}, {:.17g}] (squared {}).\n",
                          nearest_place(n), n.lo, n.hi, n.squared);
}

}  // namespace fdh::verify

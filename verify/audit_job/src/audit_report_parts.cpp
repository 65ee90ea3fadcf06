// A part's certificate read back from its audit.json and joined to the next part's: the merge of
// `fdhcert audit --part` runs into the whole run's certificate (fdh/audit_job/audit_parts.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fdh/audit_job/audit_report.hpp"
#include "fdh/io/input_error.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;
using audit::ViolationKind;

constexpr ViolationKind kReadKinds[] = {
    ViolationKind::SelfIntersection,     ViolationKind::ObstacleIntersection,
    ViolationKind::SelfVertexFace,       ViolationKind::SelfEdgeEdge,
    ViolationKind::ClothVertexObstacle,  ViolationKind::ObstacleVertexCloth,
    ViolationKind::ClothEdgeObstacleEdge};

ViolationKind kind_named(const std::string& name) {
  for (const ViolationKind k : kReadKinds)
    if (name == audit::to_string(k)) return k;
  throw std::invalid_argument("an unknown violation kind '" + name + "'");
}

// The counts of one frame (or of the totals) by kind, as counts_json wrote them.
AuditCounts counts_from(const Json& j) {
  AuditCounts c;
  for (const ViolationKind k : kReadKinds) {
    const auto it = j.find(audit::to_string(k));
    if (it == j.end()) continue;  // a frame without a step into it
    if (k == ViolationKind::SelfIntersection)
      c.self_intersections = it->get<long>();
    else if (k == ViolationKind::ObstacleIntersection)
      c.obstacle_intersections = it->get<long>();
    else
      c.step.*audit::counter_of(k) = it->get<long>();
  }
  return c;
}

KeptViolation kept_from(const Json& j) {
  KeptViolation k;
  audit::Violation& v = k.violation;
  v.kind = kind_named(j.at("kind").get<std::string>());
  v.frame = j.at("frame").get<int>();
  k.report_frame = audit::is_step(v.kind) ? v.frame + 1 : v.frame;
  if (audit::is_step(v.kind)) {
    v.vertices = j.at("vertices").get<std::array<int, 4>>();
    v.triangle = j.at("triangle").is_null() ? -1 : j.at("triangle").get<int>();
    v.toi.t_lo = j.at("toi").at("t_lo").get<double>();
    v.toi.t_hi = j.at("toi").at("t_hi").get<double>();
  } else {
    v.triangles = j.at("triangles").get<std::array<int, 2>>();
    k.corners = j.at("triangle_vertices").get<std::array<Tri, 2>>();
  }
  if (j.contains("places")) k.places = j.at("places").get<std::vector<std::string>>();
  if (j.contains("case_file")) k.case_file = j.at("case_file").get<std::string>();
  return k;
}

AuditPart part_from(const Json& j) {
  AuditPart p;
  p.index = j.at("index").get<int>(), p.of = j.at("of").get<int>();
  p.first_frame = j.at("first_frame").get<int>(), p.last_frame = j.at("last_frame").get<int>();
  p.sequence_frames = j.at("sequence_frames").get<int>();
  p.first_file = j.at("first_file").get<std::string>();
  p.last_file = j.at("last_file").get<std::string>();
  p.keep = j.at("keep").get<int>();
  return p;
}

}  // namespace

AuditReport AuditReport::from_json(const nlohmann::ordered_json& j, const std::string& file) {
  AuditReport r;
  try {
    r.options_.k = j.at("k").get<int>();
    r.sizes_ = {j.at("cloth").at("vertices").get<int>(),
                j.at("obstacles").at("vertices").get<int>(),
                j.at("cloth").at("triangles").get<std::size_t>(),
                j.at("obstacles").at("triangles").get<std::size_t>()};
    for (const Json& f : j.at("per_frame")) r.per_frame_.push_back(counts_from(f));
    r.total_ = counts_from(j.at("totals"));
    r.total_.static_candidates = j.at("candidates").at("static").get<long>();
    r.total_.step.candidates = j.at("candidates").at("ccd").get<long>();
    r.total_.inside = j.at("inside").get<long>();
    for (const Json& k : j.at("kept")) r.kept_.push_back(kept_from(k));
    if (j.contains("part")) r.part_ = part_from(j.at("part"));
    r.keep_ = r.part_ ? std::max(1, r.part_->keep) : std::max<int>(1, int(r.kept_.size()));
    r.case_files_ = true;  // a part to merge was written with --out
    const Json& cost = j.at("cost");
    r.options_.threads = cost.at("threads").get<int>();
    r.first_seconds_ = cost.value("first_frame_seconds", 0.0);
    r.step_seconds_ = cost.value("step_seconds", 0.0);
    r.wall_seconds_ = cost.value("wall_seconds", 0.0);
    r.cpu_seconds_ = cost.value("cpu_seconds", 0.0);
    r.peak_bytes_ = cost.value("peak_memory_bytes", 0L);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, 0, std::string("not an audit certificate: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, std::string("not an audit certificate: ") + e.what());
  }
  return r;
}

namespace {

// Why `b` cannot follow `a` in one sequence's parts, or "" when it can.
std::string mismatch(const AuditPart& a, const AuditPart& b) {
  if (b.of != a.of || b.index != a.index + 1)
    return fmt::format("part {}/{} cannot follow part {}/{}", b.index, b.of, a.index, a.of);
  if (b.sequence_frames != a.sequence_frames || b.first_file != a.first_file ||
      b.last_file != a.last_file)
    return fmt::format(
        "a part of another sequence ({} frames, {} to {}; part {}: {} frames, {} "
        "to {})",
        b.sequence_frames, b.first_file, b.last_file, a.index, a.sequence_frames, a.first_file,
        a.last_file);
  if (b.first_frame != a.last_frame)
    return fmt::format("starts at frame {}, and part {} ends at frame {}", b.first_frame, a.index,
                       a.last_frame);
  if (b.keep != a.keep)
    return fmt::format("--keep {}, and part {} has {}", b.keep, a.index, a.keep);
  return "";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> AuditReport::append(const AuditReport& later) {
  std::string why = !part_ || !later.part_ ? "only parts (audit --part) are joined"
                                           : mismatch(*part_, *later.part_);
  if (why.empty() &&
      (later.options_.k != options_.k || later.sizes_.cloth_vertices != sizes_.cloth_vertices ||
       later.sizes_.obstacle_vertices != sizes_.obstacle_vertices))
    why = "another --k or another topology";
  if (!why.empty()) throw std::invalid_argument(why);
  per_frame_.insert(per_frame_.end(), later.per_frame_.begin(), later.per_frame_.end());
  total_.add(later.total_);
  std::vector<std::pair<std::string, std::string>> renamed;
  for (KeptViolation k : later.kept_) {
    if (int(kept_.size()) >= keep_) break;
    if (!k.case_file.empty()) {
      const std::string name = fmt::format("cases/{:03d}-{}-step-{}.vf", kept_.size() + 1,
                                           audit::to_string(k.violation.kind), k.violation.frame);
      renamed.emplace_back(k.case_file, name);
      k.case_file = name;
    }
    kept_.push_back(std::move(k));
  }
  // Each part builds the trees once: the first frames' cost is every part's.
  first_seconds_ += later.first_seconds_, step_seconds_ += later.step_seconds_;
  wall_seconds_ += later.wall_seconds_, cpu_seconds_ += later.cpu_seconds_;
  peak_bytes_ = std::max(peak_bytes_, later.peak_bytes_);
  part_->index = later.part_->index, part_->last_frame = later.part_->last_frame;
  return renamed;
}

void AuditReport::end_parts() {
  if (!part_ || part_->first_frame != 0 || part_->index != part_->of)
    throw std::invalid_argument(
        part_ ? fmt::format("the last part given is {}/{}: every part 1/N to N/N is needed",
                            part_->index, part_->of)
              : std::string("only parts (audit --part) are joined"));
  part_.reset();  // the whole run's
}

}  // namespace fdh::verify

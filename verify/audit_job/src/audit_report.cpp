#include "fdh/audit_job/audit_report.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;
using audit::AuditCounts;
using audit::count_of;
using audit::counts_of;
using audit::ViolationKind;

constexpr ViolationKind kKinds[] = {
    ViolationKind::SelfIntersection,     ViolationKind::ObstacleIntersection,
    ViolationKind::SelfVertexFace,       ViolationKind::SelfEdgeEdge,
    ViolationKind::ClothVertexObstacle,  ViolationKind::ObstacleVertexCloth,
    ViolationKind::ClothEdgeObstacleEdge};

// The kinds a run counts: the proximity kinds only with a minimum distance (so that an audit
// without one writes what it wrote before they existed).
std::vector<ViolationKind> kinds_of(const audit::Options& o) {
  std::vector<ViolationKind> out(std::begin(kKinds), std::end(kKinds));
  if (o.min_distance > 0)
    for (const ViolationKind k : kKinds) out.push_back(audit::proximity_kind(k));
  return out;
}

// Which of a step violation's four query vertices are the cloth's (the rest are the
// obstacles'), in fdh::Query's order (vertex-face: v f0 f1 f2; edge-edge: a0 a1 b0 b1).
std::array<bool, 4> cloth_vertices_of(ViolationKind k) {
  switch (audit::contact_kind(k)) {
    case ViolationKind::ClothVertexObstacle:
      return {true, false, false, false};
    case ViolationKind::ObstacleVertexCloth:
      return {false, true, true, true};
    case ViolationKind::ClothEdgeObstacleEdge:
      return {true, true, false, false};
    default:
      return {true, true, true, true};
  }
}

// FILE:LINE of each primitive of v: a step's four vertices, a frame's two triangles.
std::vector<std::string> places_of(const audit::Violation& v, const FramePlaces& p) {
  std::vector<std::string> out;
  if (!audit::is_step(v.kind)) {
    const bool self = audit::contact_kind(v.kind) == ViolationKind::SelfIntersection;
    if (!p.cloth_tris || !(self ? p.cloth_tris : p.obstacle_tris)) return out;
    out.push_back(p.cloth_tris->at(v.triangles[0]));
    out.push_back((self ? p.cloth_tris : p.obstacle_tris)->at(v.triangles[1]));
    return out;
  }
  const std::array<bool, 4> cloth = cloth_vertices_of(v.kind);
  for (int i = 0; i < 4; ++i) {
    const Places* at = cloth[std::size_t(i)] ? p.cloth_vertices : p.obstacle_vertices;
    if (!at) return {};
    out.push_back(at->at(v.vertices[std::size_t(i)]));
  }
  return out;
}

Json toi_json(const audit::Violation& v) {
  if (!audit::is_step(v.kind)) return nullptr;
  return {{"t_lo", v.toi.t_lo}, {"t_hi", v.toi.t_hi}};
}

// "self-vertex-face at step 3 -> 4 (t in [0.25, 0.25]): vertices 1 2 3 4"
std::string describe(const audit::Violation& v) {
  if (!audit::is_step(v.kind))
    return fmt::format("{} at frame {}: triangles {} and {}", audit::to_string(v.kind), v.frame,
                       v.triangles[0], v.triangles[1]);
  return fmt::format("{} in step {} -> {} (t in [{:.17g}, {:.17g}]): vertices {} {} {} {}",
                     audit::to_string(v.kind), v.frame, v.frame + 1, v.toi.t_lo, v.toi.t_hi,
                     v.vertices[0], v.vertices[1], v.vertices[2], v.vertices[3]);
}

// "2 self-intersection; in the step from 3: 1 self-vertex-face": a frame's nonzero counts.
std::string frame_counts(const AuditCounts& c, int frame, const std::vector<ViolationKind>& kinds) {
  std::string in_frame, in_step;
  for (const ViolationKind k : kinds) {
    std::string& s = audit::is_step(k) ? in_step : in_frame;
    if (const long n = count_of(c, k))
      s += fmt::format("{}{} {}", s.empty() ? "" : ", ", n, audit::to_string(k));
  }
  if (in_step.empty()) return in_frame;
  in_step = fmt::format("in the step from {}: {}", frame - 1, in_step);
  return in_frame.empty() ? in_step : in_frame + "; " + in_step;
}

}  // namespace

AuditReport::AuditReport(const audit::Topology& topology, const audit::Options& options, int keep,
                         bool case_files)
    : topology_(topology),
      sizes_{topology.cloth_vertices, topology.obstacle_vertices, topology.cloth.size(),
             topology.obstacle.size()},
      options_(options),
      keep_(std::max(1, keep)),
      case_files_(case_files) {}

AuditPart AuditPart::of_sequence(int index, int of, int frames) {
  const long steps = std::max(0, frames - 1);
  if (index < 1 || index > of || (of > 1 && of > steps))
    throw std::invalid_argument(fmt::format(
        "part {}/{}: the parts are 1/N to N/N, each of at least one step, and the sequence has {} "
        "steps",
        index, of, steps));
  AuditPart p;
  p.index = index, p.of = of, p.sequence_frames = frames;
  p.first_frame = int((index - 1) * steps / of);
  p.last_frame = of == 1 ? frames - 1 : int(index * steps / of);
  return p;
}

void AuditReport::set_part(const AuditPart& part) {
  part_ = part;
  part_->keep = keep_;
}

int AuditReport::steps() const {
  const int counted = frames();
  return std::max(0, frame_number(0) == 0 ? counted - 1 : counted);
}

bool AuditReport::add(const audit::FrameReport& r, const FramePlaces* step_start,
                      const FramePlaces* frame) {
  const bool was_clean = clean();
  const AuditCounts c = counts_of(r);
  per_frame_.push_back(c);
  total_.add(c);
  (per_frame_.size() == 1 && frame_number(0) == 0 ? first_seconds_ : step_seconds_) += r.seconds;
  // The nearest pairs of the run: the least lower bound, the earliest frame on ties.
  for (int i = 0; i < 2; ++i) {
    const audit::Nearest& n = r.nearest[std::size_t(i)];
    if (n.frame >= 0 && (nearest_[i].frame < 0 || n.lo < nearest_[i].lo)) nearest_[i] = n;
  }
  for (const audit::Violation& v : r.violations) {
    if (int(kept_.size()) >= keep_) break;
    KeptViolation k{v, r.frame, {}, {}, {}};
    if (!audit::is_step(v.kind)) {
      const bool self = audit::contact_kind(v.kind) == ViolationKind::SelfIntersection;
      k.corners = {topology_.cloth[std::size_t(v.triangles[0])],
                   (self ? topology_.cloth : topology_.obstacle)[std::size_t(v.triangles[1])]};
    }
    const FramePlaces* p = audit::is_step(v.kind) ? step_start : frame;
    if (p) k.places = places_of(v, *p);
    if (case_files_ && audit::is_step(v.kind))
      k.case_file = fmt::format("cases/{:03d}-{}-step-{}.vf", kept_.size() + 1,
                                audit::to_string(v.kind), v.frame);
    kept_.push_back(std::move(k));
  }
  return was_clean && !clean();
}

void AuditReport::finish(double wall_seconds) {
  wall_seconds_ = wall_seconds;
  rusage u{};
  if (::getrusage(RUSAGE_SELF, &u) != 0) return;
  peak_bytes_ = long(u.ru_maxrss) * 1024;  // KiB on Linux
  cpu_seconds_ = double(u.ru_utime.tv_sec) + double(u.ru_stime.tv_sec) +
                 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

QueryRecord case_record(const KeptViolation& k) {
  const audit::Violation& v = k.violation;
  QueryRecord q;
  q.query = v.query;
  q.id = fmt::format("{}-step-{}-v{}-{}-{}-{}", audit::to_string(v.kind), v.frame, v.vertices[0],
                     v.vertices[1], v.vertices[2], v.vertices[3]);
  q.truth = Truth::Yes;
  q.file = k.case_file;
  return q;
}

std::vector<QueryRecord> AuditReport::case_records() const {
  std::vector<QueryRecord> out;
  for (const KeptViolation& k : kept_)
    if (!k.case_file.empty()) out.push_back(case_record(k));
  return out;
}

namespace {

// "1 frame", "2 frames".
std::string counted(long n, const char* what) {
  return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
}

}  // namespace

std::string AuditReport::summary_line() const {
  // A part's: "part 2/3 of 101 frames: frames 33 to 66, 33 steps" (it counts frames 34 to 66).
  const std::string what =
      part_ ? fmt::format("part {}/{} of {}: frames {} to {}, {}", part_->index, part_->of,
                          counted(part_->sequence_frames, "frame"), part_->first_frame,
                          part_->last_frame, counted(steps(), "step"))
            : counted(frames(), "frame") + ", " + counted(steps(), "step");
  const std::string near = options_.min_distance > 0 ? "; " + nearest_words(*this) : "";
  if (clean()) return fmt::format("clean: {}, 0 violations (exact){}", what, near);
  return fmt::format("VIOLATION: {}, {}; first: {}{}", what, counted(total_.total(), "violation"),
                     describe(kept_.front().violation), near);
}

std::string AuditReport::text(int max_frames) const {
  std::string out = summary_line() + "\n";
  int shown = 0, more = 0;
  for (std::size_t f = 0; f < per_frame_.size(); ++f) {
    const AuditCounts& c = per_frame_[f];
    if (c.total() == 0) continue;
    if (shown == max_frames) {
      ++more;
      continue;
    }
    ++shown;
    out += fmt::format("  frame {}: {}\n", frame_number(f),
                       frame_counts(c, frame_number(f), kinds_of(options_)));
  }
  if (more) out += fmt::format("  ... and {} more frames with violations\n", more);
  if (total_.inside > 0)
    out += fmt::format(
        "  {} cloth vertices strictly inside a closed obstacle, summed over the frames\n",
        total_.inside);
  return out;
}

namespace {

Json counts_json(const AuditCounts& c, bool with_step, const std::vector<ViolationKind>& kinds) {
  Json j;
  for (const ViolationKind k : kinds)
    if (with_step || !audit::is_step(k)) j[audit::to_string(k)] = count_of(c, k);
  return j;
}

Json violation_json(const KeptViolation& k) {
  const audit::Violation& v = k.violation;
  Json j = {{"kind", audit::to_string(v.kind)}, {"step", audit::is_step(v.kind)}};
  if (audit::is_step(v.kind)) {
    j["frame"] = v.frame, j["to_frame"] = v.frame + 1;
    j["vertices"] = v.vertices;
    j["triangle"] = v.triangle >= 0 ? Json(v.triangle) : Json(nullptr);
  } else {
    j["frame"] = v.frame;
    j["triangles"] = v.triangles;
    j["triangle_vertices"] = k.corners;
  }
  j["toi"] = toi_json(v);
  if (!k.places.empty()) j["places"] = k.places;
  if (!k.case_file.empty()) j["case_file"] = k.case_file;
  return j;
}

}  // namespace

nlohmann::ordered_json AuditReport::json() const {
  Json j = {{"clean", clean()},
            {"summary", summary_line()},
            {"frames", frames()},
            {"steps", steps()},
            {"cloth", {{"vertices", sizes_.cloth_vertices}, {"triangles", sizes_.cloth_triangles}}},
            {"obstacles",
             {{"vertices", sizes_.obstacle_vertices}, {"triangles", sizes_.obstacle_triangles}}},
            {"k", options_.k},
            {"violations", total_.total()},
            {"totals", counts_json(total_, true, kinds_of(options_))},
            {"candidates", {{"static", total_.static_candidates}, {"ccd", total_.step.candidates}}},
            {"inside", total_.inside}};
  if (options_.min_distance > 0) j["proximity"] = proximity_json(*this);
  j["first_violation"] = kept_.empty() ? Json(nullptr) : violation_json(kept_.front());
  Json frames_j = Json::array();
  for (std::size_t f = 0; f < per_frame_.size(); ++f) {
    Json one = {{"frame", frame_number(f)}};
    one.update(counts_json(per_frame_[f], frame_number(f) > 0, kinds_of(options_)));
    frames_j.push_back(std::move(one));
  }
  j["per_frame"] = std::move(frames_j);
  Json kept = Json::array();
  for (const KeptViolation& k : kept_) kept.push_back(violation_json(k));
  j["kept"] = std::move(kept);
  if (part_)
    j["part"] = {{"index", part_->index},
                 {"of", part_->of},
                 {"first_frame", part_->first_frame},
                 {"last_frame", part_->last_frame},
                 {"sequence_frames", part_->sequence_frames},
                 {"first_file", part_->first_file},
                 {"last_file", part_->last_file},
                 {"keep", part_->keep}};
  j["cost"] = cost_json();
  return j;
}

// The first frame's cost (the trees and the boundary loops, built once, and its checks) apart
// from the steps': the cost per vertex per step is the steps' alone.
nlohmann::ordered_json AuditReport::cost_json() const {
  const double vertex_steps = double(steps()) * sizes_.cloth_vertices;
  return {{"audit_seconds", six_digits(first_seconds_ + step_seconds_)},
          {"first_frame_seconds", six_digits(first_seconds_)},
          {"step_seconds", six_digits(step_seconds_)},
          {"wall_seconds", six_digits(wall_seconds_)},
          {"cpu_seconds", six_digits(cpu_seconds_)},
          {"ns_per_vertex_step",
           vertex_steps > 0 ? Json(six_digits(step_seconds_ * 1e9 / vertex_steps)) : Json()},
          {"peak_memory_bytes", peak_bytes_},
          {"threads", options_.threads}};
}

std::string AuditReport::markdown() const {
  const int steps = this->steps();
  std::string md = "# Audit\n\n**" + summary_line() + "**\n\n";
  md += fmt::format(
      "Cloth: {} vertices, {} triangles; obstacles: {} vertices, {} triangles; {}, {}; FDH k = "
      "{}.\n\n",
      sizes_.cloth_vertices, sizes_.cloth_triangles, sizes_.obstacle_vertices,
      sizes_.obstacle_triangles, counted(frames(), "frame"), counted(steps, "step"), options_.k);
  md += "| kind | count |\n|---|---|\n";
  for (const ViolationKind k : kinds_of(options_))
    md += fmt::format("| {} | {} |\n", audit::to_string(k), count_of(total_, k));
  if (options_.min_distance > 0) md += "\n" + proximity_markdown(*this);
  if (!kept_.empty()) {
    // With case files the run writes the picture beside this file (`audit --out`).
    const bool near = audit::is_proximity(kept_.front().violation.kind);
    if (case_files_)
      md += fmt::format("\n![the first violation, its triangles in {}](first-violation.png)\n",
                        near ? "yellow" : "blue");
    md += fmt::format("\n## The first {} violations, earliest first\n\n", kept_.size());
    md += "| # | what | where | case file |\n|---|---|---|---|\n";
    for (std::size_t i = 0; i < kept_.size(); ++i) {
      std::string where;
      for (const std::string& p : kept_[i].places)
        where += (where.empty() ? "" : ", ") + printable(p);
      md += fmt::format("| {} | {} | {} | {} |\n", i + 1, describe(kept_[i].violation), where,
                        kept_[i].case_file);
    }
    md +=
        "\n## Frames with violations\n\n| frame | in the frame; in the step into it |\n|---|---|\n";
    for (std::size_t f = 0; f < per_frame_.size(); ++f) {
      if (per_frame_[f].total() == 0) continue;
      md += fmt::format("| {} | {} |\n", frame_number(f),
                        frame_counts(per_frame_[f], frame_number(f), kinds_of(options_)));
    }
  }
  md += fmt::format(
      "\nCost: {:.3f} s of audit, {:.3f} s of it the first frame ({:.3f} s in all, reading "
      "included), peak memory {} MiB.\n",
      first_seconds_ + step_seconds_, first_seconds_, wall_seconds_, peak_bytes_ >> 20);
  return md;
}

}  // namespace fdh::verify

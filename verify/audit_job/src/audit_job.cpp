#include "fdh/audit_job/audit_job.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/kdop.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/folders.hpp"
#include "fdh/os/output_folder.hpp"
#include "violation_picture.hpp"

namespace fdh::verify {

void AuditOptions::validate() const {
  if (!is_valid_k(k))
    throw std::invalid_argument(fmt::format("k must be 6, 14, 18 or 26, not {}", k));
  if (threads < 0)
    throw std::invalid_argument(fmt::format("threads must be 0 or more, not {}", threads));
  if (keep < 1) throw std::invalid_argument(fmt::format("keep must be 1 or more, not {}", keep));
  if (up < -1 || up > 2)
    throw std::invalid_argument(fmt::format("up must be 0, 1 or 2 (x, y, z), not {}", up));
  if (part < 0 || parts < 1 || part > parts)
    throw std::invalid_argument(fmt::format("part {}/{}: takes I/N with 1 <= I <= N", part, parts));
  if (!(min_distance >= 0 && std::isfinite(min_distance)))
    throw std::invalid_argument(
        fmt::format("min_distance must be a finite number >= 0, not {}", min_distance));
  if (near_rings < 0 || near_rings > 100)
    throw std::invalid_argument(fmt::format("near_rings must be in [0, 100], not {}", near_rings));
}

audit::Options AuditOptions::engine() const {
  audit::Options a;
  a.k = k, a.keep = keep, a.threads = threads;
  a.min_distance = min_distance, a.near_rings = near_rings, a.near_first_frame = near_first_frame;
  return a;
}

ObjFrames::ObjFrames(const MeshSequence& seq) : seq_(seq) {
  const SequenceTopology& s = seq.topology();
  topology_.cloth_vertices = s.cloth_vertices, topology_.cloth = s.cloth;
  topology_.obstacle_vertices = s.obstacle_vertices, topology_.obstacle = s.obstacle;
}

std::string ObjFrames::name(int i) const {
  return seq_.files()[std::size_t(i)];
}

nlohmann::ordered_json AuditResult::to_json() const {
  return report_.json();
}

std::string AuditResult::text() const {
  return report_.text();
}

std::string written_lines(const AuditReport& report, const std::string& dir) {
  std::string text =
      fmt::format("certificate    {0}/audit.json, {0}/audit.md{1}\n", dir,
                  report.clean() ? "" : fmt::format(", {}/first-violation.png", dir));
  long cases = 0;
  for (const KeptViolation& k : report.kept()) cases += !k.case_file.empty();
  if (cases) text += fmt::format("case files     {}/cases/*.vf ({})\n", dir, cases);
  return text;
}

std::vector<std::string> audit_outputs() {
  return {"audit.json", "audit.md", "first-violation.png", "cases"};
}

std::string AuditResult::written_text(const std::string& dir) const {
  return written_lines(report_, dir);
}

void AuditResult::write(const std::string& dir) const {
  OutputFolder out(dir, audit_outputs());  // published whole: issue 34
  out.publish([&](const std::string& into) { write_into(into); });
}

void AuditResult::write_into(const std::string& dir) const {
  write_file_atomically(dir + "/audit.json", json_text(report_.json(), "audit.json"));
  write_file_atomically(dir + "/audit.md", report_.markdown());
  if (!picture_.empty()) write_file_atomically(dir + "/first-violation.png", picture_);
  for (const KeptViolation& k : report_.kept()) {
    if (k.case_file.empty()) continue;
    make_folder(dir + "/cases");
    const std::size_t f = std::size_t(k.violation.frame);
    std::ostringstream os;
    os << "# fdhcert audit: " << audit::to_string(k.violation.kind) << " in the step from "
       << printable(names_[f]) << " to " << printable(names_[f + 1]) << "\n";
    write_native(os, case_record(k));
    write_file_atomically(dir + "/" + k.case_file, os.str());
  }
}

namespace {

// The places of a frame's primitives, kept until the next frame has been audited (a step's
// violations are named in the frame the step starts from).
struct Placed {
  Places cv, ct, ov, ot;
  FramePlaces places() const { return {&cv, &ct, &ov, &ot}; }
};

std::string detail_of(const audit::FrameReport& r) {
  const long n = audit::counts_of(r).total();
  return n ? fmt::format("{} violations in frame {}", n, r.frame) : std::string();
}

// The engine's refusal of frame `i` (-1: of the faces), named by its file when it has one, else
// by the frame's index.
[[noreturn]] void refuse(const std::string& file, int i, const std::invalid_argument& e) {
  if (!file.empty()) throw InputError(file, 0, e.what());
  if (i < 0) throw;
  throw std::invalid_argument(fmt::format("frame {}: {}", i, e.what()));
}

}  // namespace

namespace {

// A part's range, and its trees built over frame 0 as the whole run's (Auditor::start_part, its
// seconds in `seconds`); the whole run without --part.
AuditPart start(FrameSource& source, const AuditOptions& o, audit::Auditor& auditor,
                double& seconds, std::vector<Vec3>& frame0) {
  const int n = source.frames();
  AuditPart part = AuditPart::of_sequence(std::max(1, o.part), o.parts, n);
  part.first_file = source.name(0), part.last_file = source.name(n - 1);
  if (part.first_frame > 0) {
    MeshFrame m = source.read(0);
    if (o.files && o.up < 0) frame0 = m.cloth;  // the whole run's picture, in any part
    const auto begin = std::chrono::steady_clock::now();
    try {
      auditor.start_part(part.first_frame, m.cloth, m.obstacle);
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    } catch (const std::invalid_argument& e) {
      refuse(m.file, 0, e);
    }
  }
  return part;
}

}  // namespace

AuditResult run_audit(FrameSource& source, const AuditOptions& o, const ProgressSink& progress) {
  o.validate();
  const auto start_time = std::chrono::steady_clock::now();
  const audit::Topology& t = source.topology();
  std::optional<audit::Auditor> auditor;
  try {
    auditor.emplace(t, o.engine());
  } catch (const std::invalid_argument& e) {  // the reader checks the faces: not expected
    refuse(source.name(0), -1, e);
  }
  AuditResult result(AuditReport(t, o.engine(), o.keep, o.files));
  double trees_seconds = 0;
  std::vector<Vec3> frame0;  // frame 0's cloth: the picture's up axis from the data
  const AuditPart part = start(source, o, *auditor, trees_seconds, frame0);
  if (o.part > 0) result.report_.set_part(part);
  result.names_.resize(std::size_t(source.frames()));
  Placed prev;
  for (int i = part.first_frame; i <= part.last_frame; ++i) {
    MeshFrame m = source.read(i);
    if (i == 0 && o.files && o.up < 0) frame0 = m.cloth;
    audit::FrameReport r;
    try {
      r = auditor->add_frame(m.cloth, m.obstacle);
    } catch (const std::invalid_argument& e) {
      refuse(m.file, i, e);
    }
    result.names_[std::size_t(i)] = source.name(i);
    Placed now{std::move(m.cloth_vertices), std::move(m.cloth_tris), std::move(m.obstacle_vertices),
               std::move(m.obstacle_tris)};
    const FramePlaces before = prev.places(), here = now.places();
    bool first = false;
    if (i == part.first_frame && i > 0) {  // the previous part's last frame, counted there
      r.seconds += trees_seconds;
      result.report_.add_shared(r);
    } else {
      first = source.placed() ? result.report_.add(r, &before, &here) : result.report_.add(r);
    }
    if (first && o.files) {
      const int up = o.up >= 0 ? o.up : up_axis_of(frame0, m.cloth, m.obstacle);
      result.first_ = AuditResult::FirstFrame{std::move(m.cloth), std::move(m.obstacle), up};
    }
    prev = std::move(now);
    report(progress, {"audit", i - part.first_frame + 1, part.last_frame - part.first_frame + 1,
                      "frames", detail_of(r)});
  }
  if (result.first_ && !result.report_.kept().empty()) {  // drawn here: its memory counts too
    result.picture_ =
        violation_picture(result.first_->cloth, result.first_->obstacle,
                          result.report_.kept().front().violation, t, result.first_->up);
    result.first_.reset();
  }
  result.report_.finish(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count());
  return result;
}

}  // namespace fdh::verify

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
#include "violation_picture.hpp"

namespace fdh::verify {

void AuditOptions::validate() const {
  if (!is_valid_k(k))
    throw std::invalid_argument(fmt::format("k must be 6, 14, 18 or 26, not {}", k));
  if (threads < 0)
    throw std::invalid_argument(fmt::format("threads must be 0 or more, not {}", threads));
  if (keep < 1) throw std::invalid_argument(fmt::format("keep must be 1 or more, not {}", keep));
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

std::string AuditResult::written_text(const std::string& dir) const {
  std::string text =
      fmt::format("certificate    {0}/audit.json, {0}/audit.md{1}\n", dir,
                  report_.clean() ? "" : fmt::format(", {}/first-violation.png", dir));
  if (!report_.case_records().empty())
    text += fmt::format("case files     {}/cases/*.vf ({})\n", dir, report_.case_records().size());
  return text;
}

void AuditResult::write(const std::string& dir) const {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(dir) / "cases", ec);
  if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());
  write_file_atomically(dir + "/audit.json", json_text(report_.json(), "audit.json"));
  write_file_atomically(dir + "/audit.md", report_.markdown());
  if (first_ && !report_.kept().empty())
    write_file_atomically(dir + "/first-violation.png",
                          violation_picture(first_->cloth, first_->obstacle,
                                            report_.kept().front().violation, topology_));
  for (const KeptViolation& k : report_.kept()) {
    if (k.case_file.empty()) continue;
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

// The engine's refusal of a frame, named by its file when it has one.
[[noreturn]] void refuse(const std::string& file, const std::invalid_argument& e) {
  if (file.empty()) throw;
  throw InputError(file, 0, e.what());
}

}  // namespace

AuditResult run_audit(FrameSource& source, const AuditOptions& o, const ProgressSink& progress) {
  o.validate();
  const auto start = std::chrono::steady_clock::now();
  const audit::Topology& t = source.topology();
  std::optional<audit::Auditor> auditor;
  try {
    auditor.emplace(t, o.engine());
  } catch (const std::invalid_argument& e) {  // the reader checks the faces: not expected
    refuse(source.name(0), e);
  }
  AuditResult result(AuditReport(t, o.engine(), o.keep, o.files));
  result.topology_ = t;
  Placed prev;
  for (int i = 0; i < source.frames(); ++i) {
    MeshFrame m = source.read(i);
    audit::FrameReport r;
    try {
      r = auditor->add_frame(m.cloth, m.obstacle);
    } catch (const std::invalid_argument& e) {
      refuse(m.file, e);
    }
    result.names_.push_back(source.name(i));
    Placed now{std::move(m.cloth_vertices), std::move(m.cloth_tris), std::move(m.obstacle_vertices),
               std::move(m.obstacle_tris)};
    const FramePlaces before = prev.places(), here = now.places();
    const bool first =
        source.placed() ? result.report_.add(r, &before, &here) : result.report_.add(r);
    if (first && o.files)
      result.first_ = AuditResult::FirstFrame{std::move(m.cloth), std::move(m.obstacle)};
    prev = std::move(now);
    report(progress, {"audit", i + 1, source.frames(), "frames", detail_of(r)});
  }
  result.report_.finish(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return result;
}

}  // namespace fdh::verify

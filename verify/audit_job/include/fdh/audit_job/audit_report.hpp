// `fdhcert audit`'s certificate: the Auditor's frame reports (fdh/audit/auditor.hpp) collected
// into a summary, per-frame counts, the first violations and the cost, as JSON (`audit --json`,
// audit.json, the dict of the Python module's fdhcert.audit) and Markdown (audit.md). The one
// builder of both, so that the program and the module cannot differ (docs/audit.md,
// docs/formats.md "audit output").
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fdh/audit/auditor.hpp"
#include "fdh/audit/counts.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

// Where one frame's primitives are in the input files, for the certificate's "places"
// (FILE:LINE of each `v` and `f`); a run over arrays (Python) has none.
struct FramePlaces {
  const Places* cloth_vertices = nullptr;
  const Places* cloth_tris = nullptr;
  const Places* obstacle_vertices = nullptr;
  const Places* obstacle_tris = nullptr;
};

// A violation kept for the certificate, with what the run adds to it.
struct KeptViolation {
  audit::Violation violation;
  int report_frame = 0;             // the frame report that carried it (a step's end frame)
  std::vector<std::string> places;  // FILE:LINE of its primitives; empty from arrays
  std::string case_file;            // relative to the --out folder; "" when none is written
  std::array<Tri, 2> corners{};     // a frame kind's two triangles' vertices
};

// A part of a sequence (`fdhcert audit --part I/N`): the I-th of N contiguous ranges of steps,
// [(I-1)S/N, I S/N) of the sequence's S = frames - 1; frames first_frame to last_frame, shared
// with the neighbours. The part certifies its steps and the frames they end in, and part 1 also
// frame 0: the parts' certificates add up to the whole run's (fdh/audit_job/audit_parts.hpp).
struct AuditPart {
  int index = 1, of = 1;
  int first_frame = 0, last_frame = 0;
  int sequence_frames = 0;
  std::string first_file, last_file;  // the sequence's, to tell parts of one run apart
  int keep = 16;
  // Part I of N of a sequence of `frames` (1 <= I <= N <= frames - 1, or N = 1); throws
  // std::invalid_argument otherwise.
  static AuditPart of_sequence(int index, int of, int frames);
  int counted_from() const { return first_frame == 0 ? 0 : first_frame + 1; }
};

using audit::AuditCounts;  // what the certificate counts, per frame and in total

// A kept step violation's case: its query, an id naming the kind, the step and the vertices, the
// exact truth 1, and `file` its case file.
QueryRecord case_record(const KeptViolation& k);

class AuditReport;

// With a minimum distance D (audit::Options::min_distance > 0; proximity_report.cpp): the
// summary's words on the nearest pair ("nearest 0.015625 ..."), and the certificate's block on D,
// the near rule and what it left out, and the nearest pair.
std::string nearest_words(const AuditReport& r);
nlohmann::ordered_json proximity_json(const AuditReport& r);
std::string proximity_markdown(const AuditReport& r);

class AuditReport {
 public:
  // `keep`: the violations kept in the certificate, earliest first (at least 1);
  // `case_files` (a run that writes its files, `audit --out`): name a case file
  // (cases/NNN-KIND-step-F.vf) for each kept step violation, and show first-violation.png in the
  // Markdown.
  AuditReport(const audit::Topology& topology, const audit::Options& options, int keep,
              bool case_files = false);

  // The next frame's report, in order. `places`: where the frames' primitives are, indexed by
  // frame (a step's violations are named in the frame the step starts from); null from arrays.
  // Returns true when this report holds the run's first violation.
  bool add(const audit::FrameReport& r, const FramePlaces* step_start = nullptr,
           const FramePlaces* frame = nullptr);

  // A part's report (before any frame): frames numbered from part.counted_from(), and its
  // range in the JSON.
  void set_part(const AuditPart& part);
  const std::optional<AuditPart>& part() const { return part_; }
  // The part's first frame (its neighbour's last): only its cost is counted, as the part's
  // first frame's.
  void add_shared(const audit::FrameReport& r) { first_seconds_ += r.seconds; }

  // The report of the next part joined after this one's (the parts in order): frames, counts,
  // kept violations (up to `keep`; their case files renumbered: the pairs (later's name, the
  // new name) are returned) and costs. Throws std::invalid_argument for a part that does not
  // follow this one in the same run.
  std::vector<std::pair<std::string, std::string>> append(const AuditReport& later);
  // Parts 1/N to N/N joined: the report is now the whole run's. Throws std::invalid_argument
  // when the last part joined is not N/N.
  void end_parts();
  // A report as its json() wrote it (a part's audit.json, for the merge); throws InputError
  // naming `file` for what json() does not write.
  static AuditReport from_json(const nlohmann::ordered_json& j, const std::string& file);

  // The run is over: `wall_seconds` from the start (reading included) and the process's peak
  // memory (getrusage's ru_maxrss), for the cost block.
  void finish(double wall_seconds);

  bool clean() const { return total_.total() == 0; }
  int exit_status() const { return clean() ? 0 : 1; }
  int frames() const { return int(per_frame_.size()); }
  int steps() const;
  const AuditCounts& totals() const { return total_; }
  const std::vector<KeptViolation>& kept() const { return kept_; }
  const audit::Options& options() const { return options_; }
  const audit::Topology& topology() const { return topology_; }
  // With a minimum distance: the nearest pair of triangles the run looked at, of the cloth
  // against itself (0) and against the obstacles (1); frame -1: none.
  const audit::Nearest& nearest(int i) const { return nearest_[std::size_t(i)]; }

  // The replayable case files of the kept step violations: the query with its exact truth (1),
  // `file` set to its name under the --out folder (case_record of each with a case file).
  std::vector<QueryRecord> case_records() const;

  // "clean: 40 frames, 39 steps, 0 violations" or "VIOLATION: ... first ... at step 3 (...)".
  std::string summary_line() const;
  // The terminal's text: the summary line, then a line per frame with violations (at most
  // `max_frames` of them, then how many more).
  std::string text(int max_frames = 20) const;
  nlohmann::ordered_json json() const;  // docs/formats.md, "audit output"
  std::string markdown() const;         // audit.md

 private:
  struct Sizes {  // the topology's
    int cloth_vertices = 0, obstacle_vertices = 0;
    std::size_t cloth_triangles = 0, obstacle_triangles = 0;
  };
  AuditReport() = default;
  nlohmann::ordered_json cost_json() const;
  int frame_number(std::size_t i) const { return (part_ ? part_->counted_from() : 0) + int(i); }

  audit::Topology topology_;  // for the corners of what add() keeps; empty from_json
  Sizes sizes_;
  audit::Options options_;
  int keep_ = 1;
  bool case_files_ = false;
  std::vector<AuditCounts> per_frame_;
  AuditCounts total_;
  std::vector<KeptViolation> kept_;
  std::array<audit::Nearest, 2> nearest_;
  std::optional<AuditPart> part_;
  // Costs: the first frame (the trees, the boundary loops, its checks) apart from the steps'.
  double first_seconds_ = 0, step_seconds_ = 0, wall_seconds_ = 0, cpu_seconds_ = 0;
  long peak_bytes_ = 0;
};

}  // namespace fdh::verify

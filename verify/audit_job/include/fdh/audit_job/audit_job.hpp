// The audit job (`fdhcert audit`, Python's fdhcert.audit): a frame source (OBJ frames from disk,
// or arrays from Python) through the audit engine (fdh/audit/auditor.hpp), streaming (one frame
// read, audited and dropped at a time), into a Result: the certificate
// (fdh/audit_job/audit_report.hpp) with its picture and case files. The CLI and Python only adapt
// their inputs and print it.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

#include "fdh/audit/auditor.hpp"
#include "fdh/audit_job/audit_report.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/os/progress.hpp"

namespace fdh::verify {

struct AuditOptions {
  int k = 18;       // the FDH's k: 6, 14, 18 or 26
  int threads = 0;  // 0: every core
  int keep = 16;    // violations kept in the certificate, earliest first, each with its case
  // The minimum distance D (`--min-distance`; 0: contact only) and the rule on pairs near by
  // construction (`--near-rings`, `--near-first-frame`): audit::Options' fields of those names.
  double min_distance = 0;
  int near_rings = 2;
  bool near_first_frame = true;
  // The run will write its files (Result::write): case files are named and the first
  // violation's frame is kept for the picture.
  bool files = false;
  int up = -1;  // the picture's up axis: 0, 1, 2 (x, y, z); -1: from the data
  // A part of the run (`--part I/N`): the I-th of N contiguous ranges of steps
  // (AuditPart::of_sequence); 0: the whole run.
  int part = 0, parts = 1;
  // Throws std::invalid_argument naming the option (the one check of CLI and Python values).
  void validate() const;
  audit::Options engine() const;
};

// Where the frames come from. Frames are read in order, each once.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual const audit::Topology& topology() const = 0;
  virtual int frames() const = 0;
  // Frame i's positions; from files also its file and the places of its primitives.
  virtual MeshFrame read(int i) = 0;
  virtual bool placed() const { return false; }  // read() gives places (FILE:LINE)
  // The name of frame i for a case file's first line: its file ("" from arrays).
  virtual std::string name(int) const { return ""; }
};

// OBJ frames from disk (fdh/io/mesh_sequence.hpp).
class ObjFrames : public FrameSource {
 public:
  explicit ObjFrames(const MeshSequence& seq);
  const audit::Topology& topology() const override { return topology_; }
  int frames() const override { return seq_.frames(); }
  MeshFrame read(int i) override { return seq_.read(i); }
  bool placed() const override { return true; }
  std::string name(int i) const override;

 private:
  const MeshSequence& seq_;
  audit::Topology topology_;
};

// What `audit --out DIR` writes into DIR: its files and its folder of cases.
std::vector<std::string> audit_outputs();

class AuditResult {
 public:
  const AuditReport& report() const { return report_; }
  nlohmann::ordered_json to_json() const;  // docs/formats.md, "audit output"
  std::string text() const;                // the summary line and a line per frame
  int exit_status() const { return report_.exit_status(); }
  // DIR/audit.json, DIR/audit.md, DIR/first-violation.png (with a violation) and
  // DIR/cases/*.vf (with kept violations), published whole: all of them or, on failure, DIR as
  // it was (fdh/os/output_folder.hpp; audit_outputs() are the audit's, replaced, the rest of
  // DIR is kept). Creates DIR. Needs AuditOptions::files.
  void write(const std::string& dir) const;
  // The lines that name what write(dir) wrote: the certificate, and the case files if any.
  std::string written_text(const std::string& dir) const;

 private:
  friend AuditResult run_audit(FrameSource&, const AuditOptions&, const ProgressSink&);
  void write_into(const std::string& dir) const;  // the files, into an existing folder
  explicit AuditResult(AuditReport report) : report_(std::move(report)) {}
  struct FirstFrame {
    std::vector<Vec3> cloth, obstacle;
    int up = 1;  // the picture's up axis
  };
  AuditReport report_;
  std::optional<FirstFrame> first_;
  std::string picture_;  // first-violation.png's bytes, drawn before the peak memory is taken
  std::vector<std::string> names_;  // each frame's, for the case files
};

// The lines that name what a certificate's write(dir) wrote: the certificate, and the case files
// if any.
std::string written_lines(const AuditReport& report, const std::string& dir);

// Every frame of `source` through the engine. Throws std::invalid_argument for bad options, and
// for frames the engine refuses InputError naming the frame's file (from files) or
// std::invalid_argument (from arrays).
AuditResult run_audit(FrameSource& source, const AuditOptions& options,
                      const ProgressSink& progress = {});

}  // namespace fdh::verify

// fdhcert audit: any simulator's output, a sequence of triangle-mesh frames, certified exactly.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <tuple>

#include "commands.hpp"
#include "fdh/audit_job/audit_job.hpp"
#include "fdh/audit_job/audit_parts.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"
#include "min_distance_option.hpp"

namespace fdh::verify {
namespace {

const char* const kAuditAbout =
    R"(certify a sequence of mesh frames: no penetration, decided exactly

FRAMES are OBJ or PLY files (ascii or binary), one per frame, in the order
given; or MESH CACHE: a mesh (OBJ, PLY) that gives the faces and a PC2 or MDD
point cache of its vertices' positions, frame after frame. A folder stands for
its numbered *.obj or *.ply files in natural order (frame_2 before frame_10);
its un-numbered ones beside them (a Blender bake's obstacle_*.obj) are fixed
obstacles, and the output says which is which. Every frame must have the
first frame's faces; between two frames every vertex moves linearly.
The cloth is the object named by --cloth (default: the object `cloth` if the
first frame has one, else the whole file); every other object of the frame
files is an obstacle that moves with it (as `simulate --obj` writes them).
Quads and polygons are split into triangles (fan), and the output says so.

Decided exactly (robust's filters with their exact fallbacks):
  in every frame  two cloth triangles that share no vertex intersect; a cloth
                  triangle intersects an obstacle triangle;
  in every step   a vertex passes through a triangle or an edge through an
                  edge: cloth against itself (primitives sharing no vertex),
                  cloth vertices against obstacle triangles, obstacle vertices
                  against cloth triangles, cloth edges against obstacle edges.
For each violation: the frame or the step, the primitives (indices into the
cloth's and the obstacles' vertices and triangles, and FILE:LINE of each), and
a certified enclosure of the time of impact within the step.
With --min-distance D > 0, also every pair of the kinds above that comes
within distance D without meeting (distance <= D counts): the proximity
kinds, each with its certified earliest time within D, and the nearest pair
of triangles seen with its exact distance. Pairs near by construction are
left out of them (never out of the intersection kinds): cloth pairs within
--near-rings rings of each other, and pairs already within D in the first
frame (--near-first-frame).
Also counted, beside the verdict: cloth vertices strictly inside a closed
obstacle (each connected piece of the obstacles that is a closed manifold
mesh; open pieces have no inside).)";

const char* const kAuditFooter =
    R"(Prints a summary line and a line per frame with violations (--json: the
certificate as one JSON object, docs/formats.md "audit output"). --out DIR
writes DIR/audit.json, DIR/audit.md, DIR/first-violation.png (a close-up of
the first violation, its primitives' triangles in blue, yellow for proximity,
the whole frame in an inset) and DIR/cases/*.vf, one replayable case per kept
step violation (`fdhcert classify` / `replay`, truth 1; a proximity's at
`min-distance D`), all published at once: a run that fails leaves DIR as it
was. See docs/audit.md.
--part I/N audits the I-th of N contiguous ranges of the steps (neighbouring
parts share one frame) into --out DIR; `fdhcert audit --merge DIR... --out DIR`
joins the parts' folders into the whole run's certificate (the same JSON but
for the costs). See docs/cluster.md for a Slurm array job.
Exit status: 0 clean; 1 a violation; 2 bad input (FILE:LINE: what; nothing is
written): a frame whose faces differ from the first's, a non-manifold cloth, a
degenerate face, a coordinate that is not a finite number, a line that is not
an OBJ statement (vt, vn, s, usemtl, ... are read past), a UTF-16 or UTF-32
file (a UTF-8 byte-order mark is taken), a PLY, PC2 or MDD file whose header
is bad or whose size does not match it (FILE: byte N: what), a file past the
bounds of docs/limits.md.)";

// The command line: the frame source's arguments, the outputs, and the job's options.
struct AuditCommand {
  std::vector<std::string> frames, obstacles, merge;
  std::string cloth, out, part;
  bool json = false;
  ProgressWhen progress = ProgressWhen::Auto;
  AuditOptions job;
};

const std::vector<std::string> kWritten = {"audit.json", "audit.md", "first-violation.png"};

int run_merge_command(const AuditCommand& o, const Io& io) {
  if (!o.frames.empty() || !o.part.empty())
    throw UsageError("audit: --merge takes the parts' folders, not FRAMES or --part");
  if (o.out.empty()) throw UsageError("audit: --merge needs --out DIR (the whole certificate)");
  check_output_folder(o.out, kWritten);
  const MergedAudit merged = merge_audit_parts(o.merge);
  merged.write(o.out);
  if (o.json)
    print_json(io.out, merged.to_json());
  else
    io.out << merged.text() << written_lines(merged.report(), o.out);
  return merged.exit_status();
}

int run_audit_command(AuditCommand& o, const Io& io) {
  if (!o.merge.empty()) return run_merge_command(o, io);
  if (o.frames.empty()) throw UsageError("audit: FRAMES is required (or --merge DIR...)");
  if (!o.part.empty() && o.out.empty())
    throw UsageError("audit: --part needs --out DIR (the part's certificate, for --merge)");
  if (!o.part.empty() && o.job.min_distance > 0)  // --merge does not carry the proximity block
    throw UsageError("audit: --part does not take --min-distance yet; audit the run whole");
  if (!o.out.empty()) check_output_folder(o.out, kWritten);
  const ThreadLimit threads(o.job.threads);
  const MeshSequence seq(o.frames, o.cloth, o.obstacles);
  for (const std::string& note : seq.notes()) io.err << "fdhcert: note: " << note << "\n";
  ObjFrames source(seq);
  o.job.files = !o.out.empty();
  if (!o.part.empty()) std::tie(o.job.part, o.job.parts) = i_of_n(o.part);
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  std::optional<AuditResult> result;
  try {
    result.emplace(run_audit(source, o.job, progress.sink()));
  } catch (const std::invalid_argument& e) {  // a --part past the sequence's steps
    throw UsageError("audit: --" + std::string(e.what()));
  }
  progress.clear();
  // After the run: a later frame's quads count too (the most in any one frame).
  if (const long n = seq.polygons(); n > 0)
    io.err << fmt::format(
        "fdhcert: note: {} face{} of more than three vertices {} split into triangles (fan)\n", n,
        n == 1 ? "" : "s", n == 1 ? "was" : "were");
  if (!o.out.empty()) result->write(o.out);
  if (o.json)
    print_json(io.out, result->to_json());
  else
    io.out << result->text() << (o.out.empty() ? "" : result->written_text(o.out));
  return result->exit_status();
}

void add_audit_options(CLI::App& cmd, AuditCommand& o) {
  cmd.add_option("FRAMES", o.frames,
                 "OBJ or PLY files, one per frame, or folders of them; or\n"
                 "MESH CACHE (a .pc2 or .mdd point cache); required\n"
                 "unless --merge");
  cmd.add_option("--obstacle", o.obstacles,
                 "an obstacle OBJ or PLY that stands still, or a folder of one\n"
                 "per frame (as many as FRAMES); repeatable")
      ->type_name("FILE")
      ->allow_extra_args(false);
  cmd.add_option("--cloth", o.cloth,
                 "the object (`o` or `g` NAME) that is the cloth (default: the\n"
                 "object `cloth`, else the whole file)")
      ->type_name("NAME");
  cmd.add_option("--out", o.out,
                 "write audit.json, audit.md, first-violation.png and cases/\n"
                 "into DIR")
      ->type_name("DIR");
  cmd.add_option("--up", o.job.up,
                 "the picture's up axis: x, y or z (default: from the data, the\n"
                 "way the cloth falls)")
      ->type_name("AXIS")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, int>{{"x", 0}, {"y", 1}, {"z", 2}}));
  cmd.add_option("--part", o.part,
                 "audit only the I-th of N contiguous ranges of the steps\n"
                 "(neighbouring parts share a frame), into --out DIR")
      ->type_name("I/N")
      ->check(i_of_n_validator(1000000));
  cmd.add_option("--merge", o.merge,
                 "join the folders of parts 1/N to N/N (--part) into the\n"
                 "whole run's certificate in --out DIR, instead of auditing\n"
                 "FRAMES")
      ->type_name("DIR...")
      ->expected(1, -1);
  cmd.add_flag("--json", o.json, "print the certificate as one JSON object");
  cmd.add_option("--k", o.job.k, "the FDH's k: 6, 14, 18 (default) or 26")
      ->type_name("K")
      ->check(kdop_k_validator(false));
  add_number_option(cmd, "--keep", o.job.keep,
                    "violations kept in the certificate, earliest first, each\n"
                    "with its case file (default 16)",
                    "N", 1, 100000);
  add_min_distance_option(cmd, o.job.min_distance,
                          "the minimum distance D: pairs within distance D (<= D)\n"
                          "without meeting are proximity violations (default 0:\n"
                          "contact only)");
  add_number_option(cmd, "--near-rings", o.job.near_rings,
                    "with --min-distance: leave out of the proximity\n"
                    "kinds cloth pairs whose vertices are within N edges\n"
                    "of each other (default 2; 0: only those sharing a\n"
                    "vertex)",
                    "N", 0, 100);
  cmd.add_option("--near-first-frame", o.job.near_first_frame,
                 "with --min-distance: leave out pairs already within\n"
                 "D in the first frame: on (default) or off")
      ->type_name("on|off")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, bool>{{"on", true}, {"off", false}}));
  add_threads_option(cmd, o.job.threads, "the audit");
  add_quiet_flag(cmd, o.progress);
}

}  // namespace

Command add_audit(CLI::App& app) {
  auto o = std::make_shared<AuditCommand>();
  CLI::App* cmd = add_command(app, "audit", kAuditAbout, kAuditFooter);
  add_audit_options(*cmd, *o);
  return {cmd, [o](const Io& io) { return run_audit_command(*o, io); }};
}

}  // namespace fdh::verify

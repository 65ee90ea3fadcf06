// fdhcert audit: any simulator's output, a sequence of triangle-mesh frames, certified exactly.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fdh/audit_job/audit_job.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/os/atomic_file.hpp"
#include "min_distance_option.hpp"

namespace fdh::verify {
namespace {

const char* const kAuditAbout =
    R"(certify a sequence of mesh frames: no penetration, decided exactly

FRAMES are OBJ files, one per frame, in the order given; a folder stands for
its *.obj files in natural order (frame_2 before frame_10). Every frame must
have the first frame's faces; between two frames every vertex moves linearly.
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
writes DIR/audit.json, DIR/audit.md, DIR/first-violation.png (the frame of the
first violation, its primitives' triangles in blue, yellow for proximity) and
DIR/cases/*.vf, one replayable case per kept step violation (`fdhcert
classify` / `replay`, truth 1; a proximity's at `min-distance D`). See
docs/audit.md.
Exit status: 0 clean; 1 a violation; 2 bad input (FILE:LINE: what; nothing is
written): a frame whose faces differ from the first's, a non-manifold cloth, a
degenerate face, a coordinate that is not a finite number, a file past the
bounds of docs/limits.md.)";

// The command line: the frame source's arguments, the outputs, and the job's options.
struct AuditCommand {
  std::vector<std::string> frames, obstacles;
  std::string cloth, out;
  bool json = false;
  ProgressWhen progress = ProgressWhen::Auto;
  AuditOptions job;
};

int run_audit_command(AuditCommand& o, const Io& io) {
  if (!o.out.empty()) check_output_dir(o.out, {"audit.json", "audit.md", "first-violation.png"});
  const ThreadLimit threads(o.job.threads);
  const MeshSequence seq(o.frames, o.cloth, o.obstacles);
  if (seq.polygons() > 0)
    io.err << fmt::format(
        "fdhcert: note: {} faces of more than three vertices were split into triangles (fan)\n",
        seq.polygons());
  ObjFrames source(seq);
  o.job.files = !o.out.empty();
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  const AuditResult result = run_audit(source, o.job, progress.sink());
  progress.clear();
  if (!o.out.empty()) result.write(o.out);
  if (o.json)
    print_json(io.out, result.to_json());
  else
    io.out << result.text() << (o.out.empty() ? "" : result.written_text(o.out));
  return result.exit_status();
}

void add_audit_options(CLI::App& cmd, AuditCommand& o) {
  cmd.add_option("FRAMES", o.frames, "OBJ files, one per frame, or folders of them")->required();
  cmd.add_option("--obstacle", o.obstacles,
                 "an obstacle OBJ that stands still, or a folder of one OBJ per\n"
                 "frame (as many as FRAMES); repeatable")
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

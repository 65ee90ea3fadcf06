// fdhcert audit: any simulator's output, a sequence of triangle-mesh frames, certified exactly.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "fdh/audit/auditor.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_output.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/run/audit_report.hpp"
#include "fdh/run/json_text.hpp"
#include "progress.hpp"
#include "threads_option.hpp"

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
a certified enclosure of the time of impact within the step.)";

const char* const kAuditFooter =
    R"(Prints a summary line and a line per frame with violations (--json: the
certificate as one JSON object, docs/formats.md "audit output"). --out DIR
writes DIR/audit.json, DIR/audit.md, DIR/first-violation.png (the frame of the
first violation, its primitives' triangles in blue) and DIR/cases/*.vf, one
replayable case per kept step violation (`fdhcert classify` / `replay`, truth
1). See docs/audit.md.
Exit status: 0 clean; 1 a violation; 2 bad input (FILE:LINE: what; nothing is
written): a frame whose faces differ from the first's, a non-manifold cloth, a
degenerate face, a coordinate that is not a finite number, a file past the
bounds of docs/limits.md.)";

struct AuditOptions {
  std::vector<std::string> frames, obstacles;
  std::string cloth, out;
  bool json = false;
  ProgressWhen progress = ProgressWhen::Auto;
  int k = 18, threads = 0, keep = 16;
};

const std::array<double, 3> kAuditClothColour = {0.85, 0.25, 0.2},
                            kAuditObstacleColour = {0.7, 0.7, 0.65},
                            kAuditMarkColour = {0.15, 0.45, 1.0};

audit::Topology topology_of(const SequenceTopology& s) {
  audit::Topology t;
  t.cloth_vertices = s.cloth_vertices, t.cloth = s.cloth;
  t.obstacle_vertices = s.obstacle_vertices, t.obstacle = s.obstacle;
  return t;
}

// The triangles of `tris` holding every vertex of `vs` (an edge's two, or a vertex's one).
void mark_holding(const std::vector<Tri>& tris, std::vector<int> vs, std::vector<Tri>& out) {
  for (const Tri& t : tris) {
    int held = 0;
    for (const int v : vs) held += t[0] == v || t[1] == v || t[2] == v;
    if (held == int(vs.size())) out.push_back(t);
  }
}

// The first violation's triangles, the cloth's and the obstacles', for the picture.
std::pair<std::vector<Tri>, std::vector<Tri>> marked(const audit::Violation& v,
                                                     const audit::Topology& t) {
  std::vector<Tri> c, o;
  const auto& x = v.vertices;
  using K = audit::ViolationKind;
  switch (v.kind) {
    case K::SelfIntersection:
      c = {t.cloth[std::size_t(v.triangles[0])], t.cloth[std::size_t(v.triangles[1])]};
      break;
    case K::ObstacleIntersection:
      c = {t.cloth[std::size_t(v.triangles[0])]}, o = {t.obstacle[std::size_t(v.triangles[1])]};
      break;
    case K::SelfVertexFace:
      mark_holding(t.cloth, {x[0]}, c), c.push_back({x[1], x[2], x[3]});
      break;
    case K::SelfEdgeEdge:
      mark_holding(t.cloth, {x[0], x[1]}, c), mark_holding(t.cloth, {x[2], x[3]}, c);
      break;
    case K::ClothVertexObstacle:
      mark_holding(t.cloth, {x[0]}, c), o.push_back({x[1], x[2], x[3]});
      break;
    case K::ObstacleVertexCloth:
      mark_holding(t.obstacle, {x[0]}, o), c.push_back({x[1], x[2], x[3]});
      break;
    case K::ClothEdgeObstacleEdge:
      mark_holding(t.cloth, {x[0], x[1]}, c), mark_holding(t.obstacle, {x[2], x[3]}, o);
      break;
  }
  return {c, o};
}

// The frame of the first violation, kept for the picture.
struct FirstFrame {
  std::vector<Vec3> cloth, obstacle;
};

std::string picture(const FirstFrame& f, const audit::Violation& v, const audit::Topology& t) {
  const auto [mc, mo] = marked(v, t);
  // The marks first: the renderer keeps the first of two triangles at the same depth.
  std::vector<SceneMesh> meshes = {{"marked", &f.cloth, &mc, kAuditMarkColour},
                                   {"marked obstacle", &f.obstacle, &mo, kAuditMarkColour},
                                   {"cloth", &f.cloth, &t.cloth, kAuditClothColour},
                                   {"obstacles", &f.obstacle, &t.obstacle, kAuditObstacleColour}};
  return encode_png(render(meshes, 800, 600, frame_view({meshes[2], meshes[3]})));
}

// The run over the frames, streaming: frame i is read, audited, and dropped (the Auditor keeps
// the previous positions for the step).
class AuditRun {
 public:
  AuditRun(const AuditOptions& o, const MeshSequence& seq)
      : o_(o),
        seq_(seq),
        topology_(topology_of(seq.topology())),
        auditor_(make_auditor()),
        report_(topology_, options(), o.keep, !o.out.empty()) {}

  const AuditReport& run(ProgressLine& progress) {
    const auto start = std::chrono::steady_clock::now();
    Placed prev;
    for (int i = 0; i < seq_.frames(); ++i) {
      MeshFrame m = seq_.read(i);
      const audit::FrameReport r = add_frame(m);
      Placed now{std::move(m.cloth_vertices), std::move(m.cloth_tris),
                 std::move(m.obstacle_vertices), std::move(m.obstacle_tris)};
      const FramePlaces before = prev.places(), here = now.places();
      if (report_.add(r, &before, &here) && !o_.out.empty())
        first_ = FirstFrame{std::move(m.cloth), std::move(m.obstacle)};
      prev = std::move(now);
      progress.draw({"audit", i + 1, seq_.frames(), "frames", detail_of(r)});
    }
    report_.finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return report_;
  }

  void write(const std::string& dir) const {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(fs::path(dir) / "cases", ec);
    if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());
    write_file_atomically(dir + "/audit.json", json_text(report_.json(), "audit.json"));
    write_file_atomically(dir + "/audit.md", report_.markdown());
    if (first_ && !report_.kept().empty())
      write_file_atomically(dir + "/first-violation.png",
                            picture(*first_, report_.kept().front().violation, topology_));
    for (const KeptViolation& k : report_.kept()) {
      if (k.case_file.empty()) continue;
      const int f = k.violation.frame;
      std::ostringstream os;
      os << "# fdhcert audit: " << audit::to_string(k.violation.kind) << " in the step from "
         << printable(seq_.files()[std::size_t(f)]) << " to "
         << printable(seq_.files()[std::size_t(f) + 1]) << "\n";
      write_native(os, case_record(k));
      write_file_atomically(dir + "/" + k.case_file, os.str());
    }
  }

 private:
  struct Placed {
    Places cv, ct, ov, ot;
    FramePlaces places() const { return {&cv, &ct, &ov, &ot}; }
  };

  audit::Options options() const {
    audit::Options a;
    a.k = o_.k, a.keep = o_.keep, a.threads = o_.threads;
    return a;
  }

  std::unique_ptr<audit::Auditor> make_auditor() const {
    try {
      return std::make_unique<audit::Auditor>(topology_, options());
    } catch (const std::invalid_argument& e) {  // the reader checks the faces: not expected
      throw InputError(seq_.files().front(), 0, e.what());
    }
  }

  // The reader checks counts and coordinates; the engine's own check names the file if it fails.
  audit::FrameReport add_frame(const MeshFrame& m) {
    try {
      return auditor_->add_frame(m.cloth, m.obstacle);
    } catch (const std::invalid_argument& e) {
      throw InputError(m.file, 0, e.what());
    }
  }

  static std::string detail_of(const audit::FrameReport& r) {
    const long n = r.self_intersections + r.obstacle_intersections + r.step.total();
    return n ? fmt::format("{} violations in frame {}", n, r.frame) : std::string();
  }

  const AuditOptions& o_;
  const MeshSequence& seq_;
  audit::Topology topology_;
  std::unique_ptr<audit::Auditor> auditor_;
  AuditReport report_;
  std::optional<FirstFrame> first_;
};

int run_audit(const AuditOptions& o, const Io& io) {
  if (!o.out.empty()) check_output_dir(o.out, {"audit.json", "audit.md", "first-violation.png"});
  const ThreadLimit threads(o.threads);
  const MeshSequence seq(o.frames, o.cloth, o.obstacles);
  if (seq.polygons() > 0)
    io.err << fmt::format(
        "fdhcert: note: {} faces of more than three vertices were split into triangles (fan)\n",
        seq.polygons());
  AuditRun run(o, seq);
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  const AuditReport& report = run.run(progress);
  progress.clear();
  if (!o.out.empty()) run.write(o.out);
  if (o.json) {
    print_json(io.out, report.json());
    return report.exit_status();
  }
  io.out << report.text();
  if (!o.out.empty())
    io.out << fmt::format("certificate    {0}/audit.json, {0}/audit.md{1}\n", o.out,
                          report.clean() ? "" : fmt::format(", {}/first-violation.png", o.out));
  if (!report.case_records().empty())
    io.out << fmt::format("case files     {}/cases/*.vf ({})\n", o.out,
                          report.case_records().size());
  return report.exit_status();
}

void add_audit_options(CLI::App& cmd, AuditOptions& o) {
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
  cmd.add_option("--k", o.k, "the FDH's k: 6, 14, 18 (default) or 26")
      ->type_name("K")
      ->check(kdop_k_validator(false));
  add_number_option(cmd, "--keep", o.keep,
                    "violations kept in the certificate, earliest first, each\n"
                    "with its case file (default 16)",
                    "N", 1, 100000);
  add_threads_option(cmd, o.threads, "the audit");
  add_quiet_flag(cmd, o.progress);
}

}  // namespace

Command add_audit(CLI::App& app) {
  auto o = std::make_shared<AuditOptions>();
  CLI::App* cmd = add_command(app, "audit", kAuditAbout, kAuditFooter);
  add_audit_options(*cmd, *o);
  return {cmd, [o](const Io& io) { return run_audit(*o, io); }};
}

}  // namespace fdh::verify

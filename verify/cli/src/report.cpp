// fdhcert report: certificate, measurements, charts and report.md in one folder.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "fdh/certify/corpus_folder.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"
#include "fdh/report/report_document.hpp"
#include "fdh/report/report_summary.hpp"
#include "suite_commands.hpp"

namespace fdh::verify {
namespace {

const char* const kReportAbout =
    R"(certificate, measurements and charts in one folder

The verification report, as `./run verify` makes it (into docs/report):
  DIR/certificate.json, .md   fdhcert certify over the corpus, fuzzed cases
                              and the EXTRA FILES
  DIR/data/*.csv              the measurements behind the charts
  DIR/speed_accuracy.png/svg  ns per query against FP and FN rates, one point
                              per method and family, with the Pareto front
  DIR/stability.png/svg       failure rate of each method as the motion angle,
                              the distance to an edge, the distance from the
                              origin and the triangle's aspect go to their limits
  DIR/toi_speed.png/svg       how early each method's time of impact is (and
                              how often late) against ns per query, per
                              method and moving family
  DIR/toi_stability.png/svg   the same as the motion angle, the distance to an
                              edge and the depth of a tangential dip go to 0
  DIR/kdop_k.png/svg          FDH tree build, refit and traversal time against
                              candidate pairs, k = 6, 14, 18, 26
  DIR/min_distance_speed.png/svg
                              the minimum separation δ: ns per query against
                              FP + FN per method at δ = 0, 2^-40, 2^-20, 2^-10
                              times each query's size
  DIR/min_distance_stability.png/svg
                              which methods answer right at δ = D as the true
                              least distance D(1 + s) approaches D from below
                              and above (s = ±2^-10 ... ±2^-50)
  DIR/report.md               all of it, with tables
  DIR/index.html              the same as one page to browse: the charts inline
                              (hover a point for its method, family, FP, FN
                              and ns), the counterexamples linked
When done, prints the certificate's tables, or with --summary four lines.
)";

const char* const kReportFooter =
    R"(Charts need gnuplot (Debian: gnuplot-nox). Exit status 1 if the certificate
finds a violation (the report is written all the same). --quick takes smaller
samples (a quick certificate, 100 queries per family and point): for a first
look, not for the committed report.)";

struct ReportCommand : CertifyCommand {
  bool summary = false;
};

// What run_report prints when done: the certificate's tables, or its summary lines.
void print_outcome(const ReportCommand& cmd, const Report& report, const Io& io) {
  const Certificate& c = report.certificate;
  const std::filesystem::path dir(cmd.options.out_dir);
  if (cmd.summary) {
    io.out << report_summary(report) << "report: wrote " << (dir / "report.md").string() << " and "
           << (dir / "index.html").string() << " (charts " << (dir / "*.svg").string() << ")\n";
    return;
  }
  io.out << "\n"
         << certificate_section(c) << "\nreport: wrote " << (dir / "report.md").string()
         << "; certificate " << (c.certified() ? "certified" : "VIOLATED") << "\n";
}

int run_report(const ReportCommand& cmd, const Io& io) {
  CertifyOptions opt = cmd.options;
  check_output_folder(opt.out_dir, report_outputs());
  opt.corpus_dir = corpus_or_default(opt.corpus_dir);
  opt.plugins = certified_plugins();
  const ThreadLimit threads(cmd.threads, io.err);
  ProgressLine progress(io.err, progress_wanted(io, cmd.progress));
  opt.progress = progress.sink("report: certify: ");
  OutputFolder out(opt.out_dir, report_owned());  // published whole: issue 34
  opt.write_dir = out.path();
  std::string step;  // the step now running: each is announced on standard output as it starts
  const Report report = make_report(opt, [&](const Progress& p) {
    if (p.stage != step) {
      step = p.stage;
      progress.clear();
      if (!cmd.summary) io.out << "report: " << step << " ..." << std::endl;
    }
    progress.draw({"report: " + p.stage, p.done, p.total, p.unit, p.detail});
  });
  progress.clear();
  if (!cmd.summary) io.out << "report: charts ..." << std::endl;
  out.publish([&](const std::string&) { write_report(report); });
  print_outcome(cmd, report, io);
  const Certificate& c = report.certificate;
  if (c.certified()) return 0;
  io.err << "fdhcert: certify: " << c.first_violation << "\n";
  return 1;
}

}  // namespace

Command add_report(CLI::App& app) {
  auto c = std::make_shared<ReportCommand>();
  c->options.out_dir = "report";
  CLI::App* cmd = add_command(app, "report", kReportAbout, kReportFooter);
  add_certify_options(*cmd, *c);
  cmd->add_flag("--summary", c->summary,
                "print four lines when done (certified or not, the promises, the\n"
                "metamorphic and the bounding-volume counts) instead of the\n"
                "certificate's tables, and no line per step (./run verify)");
  add_plugin_option(*cmd);  // its methods join the certificate, the charts and the tables
  return {cmd, [c](const Io& io) { return run_report(*c, io); }};
}

}  // namespace fdh::verify

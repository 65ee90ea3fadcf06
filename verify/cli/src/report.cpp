// fdhcert report: certificate, measurements, charts and report.md in one folder.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "fdh/os/atomic_file.hpp"
#include "fdh/report/report_document.hpp"
#include "plugin_option.hpp"
#include "progress.hpp"
#include "suite_commands.hpp"
#include "threads_option.hpp"

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
  DIR/report.md               all of it, with tables
When done, prints the certificate's tables.
)";

const char* const kReportFooter =
    R"(Charts need gnuplot (Debian: gnuplot-nox). Exit status 1 if the certificate
finds a violation (the report is written all the same). --quick takes smaller
samples (a quick certificate, 100 queries per family and point): for a first
look, not for the committed report.)";

int run_report(const CertifyCommand& cmd, const Io& io) {
  CertifyOptions opt = cmd.options;
  check_output_dir(opt.out_dir, report_outputs());
  opt.plugins = certified_plugins();
  const ThreadLimit threads(cmd.threads, io.err);
  ProgressLine progress(io.err, progress_wanted(io, cmd.progress));
  opt.progress = progress.sink("report: certify: ");
  std::string step;  // the step now running: each is announced on standard output as it starts
  const Report report = make_report(opt, [&](const Progress& p) {
    if (p.stage != step) {
      step = p.stage;
      progress.clear();
      io.out << "report: " << step << " ..." << std::endl;
    }
    progress.draw({"report: " + p.stage, p.done, p.total, p.unit, p.detail});
  });
  progress.clear();
  io.out << "report: charts ..." << std::endl;
  write_report(report);
  const Certificate& c = report.certificate;
  io.out << "\n"
         << certificate_section(c) << "\nreport: wrote "
         << (std::filesystem::path(opt.out_dir) / "report.md").string() << "; certificate "
         << (c.certified() ? "certified" : "VIOLATED") << "\n";
  if (c.certified()) return 0;
  io.err << "fdhcert: certify: " << c.first_violation << "\n";
  return 1;
}

}  // namespace

Command add_report(CLI::App& app) {
  auto c = std::make_shared<CertifyCommand>();
  c->options.out_dir = "report";
  CLI::App* cmd = add_command(app, "report", kReportAbout, kReportFooter);
  add_certify_options(*cmd, *c);
  add_plugin_option(*cmd);  // its methods join the certificate, the charts and the tables
  return {cmd, [c](const Io& io) { return run_report(*c, io); }};
}

}  // namespace fdh::verify

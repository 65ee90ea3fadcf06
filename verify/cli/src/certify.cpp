// fdhcert certify: the fast library against the exact reference, with a certificate.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "fdh/certify/corpus_folder.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/output_folder.hpp"
#include "min_distance_option.hpp"
#include "suite_commands.hpp"

namespace fdh::verify {

namespace {

const char* const kCertifyAbout =
    R"(certify the fast library against the exact reference

Checks every method of the registry against the exact twin of its decision,
under the method's promise, and counts every check:
  - the float FDH contains the exact FDH, for k = 6, 14, 18 and 26 (all points
    of every query, the sweep BB' and the triangle DEF of static ones);
  - the FDH tree's traversal reports every primitive pair whose exact k-DOPs
    overlap (random triangle-soup pairs, swept against static);
  - each method that promises exact answers (robust) equals the twin on every
    query of each decision it makes: static vertex-face, moving vertex-face and
    edge-edge (CCD);
  - each time of impact under its time promise (robust's exact enclosure; a
    plug-in's never-late or exact-enclosure, FDH_TIME_NO_UPPER_BOUND allowed
    to a never-late one): a late time, a missed contact, a time outside
    [0, 1] ("not a time") and, for a plug-in, a call past --plugin-timeout
    ("no answer in T s") each break it; zero times and how early are counted;
  - the exact twin = the stored truth wherever a query has one (corpus,
    benchmark CSV);
  - peers (fdhcert peers, docs/peers.md): the own k-DOPs beside FCL's and
    Bullet's boxes on random and touching point sets; the own rows must show 0,
    the peers' violations are counted and the first ones shrunk into
    DIR/peers/<library>/, and CORPUS/peers is replayed.
  - every method's verdict under each metamorphic transform of each query
    (time reversal, axis order, translation, velocity, scale, relabelling;
    the scales and translations span 2^-60 to 2^60, each applied only where
    it is exact): counted per method; robust and the twin must change none,
    and each method with a promise (conservative or exact) must keep it on
    every transformed query, against the exact verdict the transform keeps.
  - minimum separation (issue 30): the methods that answer δ > 0 (robust,
    and plug-ins that declare it) against the exact δ twin, on the delta-
    generator families (N/4 each, their truths known by construction) and on
    every 8th corpus and fuzzed query asked again at δ (2^-20 of each query's
    scale, or --min-distance D), with the metamorphic transforms (the scales
    scale δ too); listed apart in the certificate.
The queries: every *.vf under the corpus folder, N fuzzed queries of each
generator family (static and moving), the narrow-phase queries of every
shipped scene (CORPUS/scenes/*.scene run with robust; every 10th frame, or
the first 600 frames and every 50th with --quick), and the EXTRA FILES
(native or benchmark CSV).
)";

const char* const kCertifyFooter =
    R"(Writes DIR/certificate.json and DIR/certificate.md: counts, seed, the CGAL and
GMP versions and the git commit. On any violation the first case of each kind
of broken promise (a method, a decision, and what broke) is saved in DIR as a
corpus file (a .vf query, or an .obj for a tree), each named in the output,
and the exit status is 1. A plug-in call past --plugin-timeout is abandoned
and counted so, on that query; the run goes on. With --budget, a run that runs out of time
stops at a clean point, writes both files whole with the stages cut short and
how far each got, says NOT CERTIFIED and exits with status 1.)";

// One line: the promised methods judged on the transformed queries, and the transforms skipped
// as inexact.
void print_judged_under_transforms(const Certificate& c, std::ostream& out) {
  out << "promises under transforms (broken / judged):";
  for (const MetamorphicCheck& m : c.metamorphic)
    if (m.judged) out << " " << m.method << " " << m.broken << "/" << m.judged;
  long applied = 0, skipped = 0;
  for (const TransformCount& t : c.metamorphic_transforms)
    applied += t.applied, skipped += t.skipped;
  out << "; transforms applied " << applied << ", skipped as inexact " << skipped << "\n";
}

// One line: every method's verdict changes under the metamorphic transforms, of the
// transformed queries checked.
void print_metamorphic(const Certificate& c, std::ostream& out) {
  out << "metamorphic (verdicts changed / transformed queries):";
  for (const MetamorphicCheck& m : c.metamorphic)
    out << " " << m.method << " " << m.violations << "/" << m.checked;
  out << "\n";
  print_judged_under_transforms(c, out);
}

// Two lines: the δ promises (violations / checked per method and decision) and the δ
// metamorphic counts.
void print_delta(const Certificate& c, std::ostream& out) {
  const DeltaStage& d = c.delta;
  if (!d.run) return;
  out << "min-distance (δ = " << d.delta_words() << "; " << d.family_queries << " delta-family, "
      << d.contact_queries << " contact queries at δ) promises (violations / checked):";
  for (const PromiseCheck& p : d.promises)
    out << " " << p.method << " " << to_string(p.decision) << " " << p.violations << "/"
        << p.checked;
  for (const TimePromiseCheck& p : d.times)
    out << " " << p.method << " " << to_string(p.decision) << " " << p.tally.broken << "/"
        << p.tally.checked;
  out << "; truth " << d.truth_violations << "/" << d.truths << "\n";
  out << "min-distance metamorphic (verdicts changed / transformed queries; promise broken / "
         "judged):";
  for (const MetamorphicCheck& m : d.metamorphic)
    out << " " << m.method << " " << m.violations << "/" << m.checked << ", " << m.broken << "/"
        << m.judged;
  out << "\n";
}

// The first word of the summary line: what the certificate says.
const char* verdict(const Certificate& c) {
  if (!c.first_violation.empty()) return "VIOLATED";
  return c.complete() ? "certified" : "NOT CERTIFIED (cut short by --budget)";
}

int run_certify(const CertifyCommand& cmd, const Io& io) {
  CertifyOptions opt = cmd.options;
  check_output_folder(opt.out_dir, {"certificate.json", "certificate.md"});
  opt.corpus_dir = corpus_or_default(opt.corpus_dir);
  opt.plugins = certified_plugins();
  const ThreadLimit threads(cmd.threads, io.err);
  ProgressLine progress(io.err, progress_wanted(io, cmd.progress));
  opt.progress = progress.sink("certify: ");
  OutputFolder out(opt.out_dir, certify_outputs());  // published whole: issue 34
  opt.write_dir = out.path();
  const Certificate c = certify(opt);  // its inputs read first: bad input prints nothing
  progress.clear();
  io.out << "corpus: " << opt.corpus_dir << "\n";
  out.publish([&](const std::string&) { write_certificate(c); });
  const std::filesystem::path dir(opt.out_dir);
  io.out << verdict(c) << ": " << c.checks() << " checks, " << c.violations() << " violations ("
         << c.corpus_queries << " corpus, " << c.fuzzed_queries << " fuzzed, " << c.scene_queries
         << " scene, " << c.extra_queries << " extra queries; " << c.options.soups
         << " soup pairs); wrote " << (dir / "certificate.md").string() << " and .json\n";
  print_metamorphic(c, io.out);
  print_delta(c, io.out);
  if (c.certified()) return 0;
  if (c.first_violation.empty()) {
    io.err << "fdhcert: certify: the budget of " << opt.budget.seconds()
           << " s ran out, so this is not a certification; cut short:";
    for (std::size_t i = 0; i < c.cut_short.size(); ++i)
      io.err << (i ? "; " : " ") << cut_words(c.cut_short[i]);
    io.err << " (" << (dir / "certificate.md").string() << ")\n";
    return 1;
  }
  for (const std::string& broken : c.broken_saved) io.err << "fdhcert: certify: " << broken << "\n";
  if (c.broken_saved.empty()) io.err << "fdhcert: certify: " << c.first_violation << "\n";
  return 1;
}

}  // namespace

std::vector<CertifiedPlugin> certified_plugins() {
  std::vector<CertifiedPlugin> out;
  for (const LoadedPlugin& p : loaded_plugins())
    out.push_back({p.file, p.name, p.settings, p.thread_safe, p.probe_cut, p.probe_calls});
  return out;
}

void add_certify_options(CLI::App& cmd, CertifyCommand& c) {
  CertifyOptions& opt = c.options;
  const CLI::Range count(0L, 1L << 30);
  cmd.add_flag("--quick", opt.quick, "200 queries per family and 30 soup pairs: under a minute");
  cmd.add_option("--out", opt.out_dir, "where the output goes (default: " + opt.out_dir + ")")
      ->type_name("DIR");
  opt.corpus_dir.clear();  // not given: corpus_or_default finds one
  cmd.add_option("--corpus", opt.corpus_dir,
                 "the corpus folder (default: ./corpus in a source checkout, else the one "
                 "installed with fdhcert, BINDIR/../share/fdhcert/corpus)")
      ->type_name("DIR");
  add_seed_option(cmd, opt.seed, "seed of the fuzzed queries and soups (default 1)");
  cmd.add_option("--per-family", opt.per_family,
                 "fuzzed queries per family (default 3000; 200 with --quick)")
      ->type_name("N")
      ->check(count);
  cmd.add_option("--soups", opt.soups, "soup pairs (default 300; 30 with --quick)")
      ->type_name("N")
      ->check(count);
  cmd.add_option("--peer-cases", opt.peer_cases,
                 "point sets, and touching pairs, per peers property (default 20000; 300 with "
                 "--quick)")
      ->type_name("N")
      ->check(count);
  add_min_distance_option(cmd, opt.min_distance,
                          "the minimum-separation stage's δ for the contact queries it\n"
                          "asks again (default: 2^-20 of each query's scale); 0 skips\n"
                          "the stage");
  cmd.add_option("--stages", opt.stages,
                 "the stages to run, in this order (default: all of\n"
                 "corpus,families,scenes,soups,extra,metamorphic,\n"
                 "min-distance,peers). metamorphic checks each query of\n"
                 "the query stages under the transforms too, wherever it\n"
                 "is listed. With a slow plug-in: --stages families,corpus,\n"
                 "say")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->type_name("LIST")
      ->check(one_of(certify_stages()));
  add_threads_option(cmd, c.threads, "the checks");
  add_quiet_flag(cmd, c.progress);
  cmd.add_option("EXTRA", opt.extra_files,
                 "more query files: native (*.vf) or CCD benchmark CSV (*.csv),\n"
                 "read before any check (a bad one is refused at once)");
}

Command add_certify(CLI::App& app) {
  auto c = std::make_shared<CertifyCommand>();
  c->options.out_dir = "certificate";
  CLI::App* cmd = add_command(app, "certify", kCertifyAbout, kCertifyFooter);
  add_certify_options(*cmd, *c);
  add_budget_option(*cmd, c->options.budget, "the checks");
  add_plugin_option(*cmd);
  return {cmd, [c](const Io& io) { return run_certify(*c, io); }};
}

}  // namespace fdh::verify

// fdhcert certify: the fast library against the exact reference, with a certificate.
#include <filesystem>

#include "commands.hpp"
#include "fdh/suite/certify.hpp"

namespace fdh::verify {
namespace {

const char* const kCertifyHelp =
    R"(usage: fdhcert certify [--quick] [--out DIR] [--corpus DIR] [--seed S]
                       [--per-family N] [--soups N] [EXTRA FILES...]

Certifies the fast library against the exact reference and counts every check:
  - the float FDH contains the exact FDH, for k = 6, 14, 18 and 26 (all points
    of every query, the sweep BB' and the triangle DEF of static ones);
  - the FDH tree's traversal reports every primitive pair whose exact k-DOPs
    overlap (random triangle-soup pairs, swept against static);
  - robust = exact on every static vertex-face query;
  - robust CCD = exact CCD on every moving vertex-face and edge-edge query;
  - exact = the stored truth wherever a query has one (corpus, benchmark CSV).
The queries: every *.vf under the corpus folder, N fuzzed queries of each
generator family (static and moving), the narrow-phase queries of every
shipped scene (CORPUS/scenes/*.scene run with robust; every 10th frame, or
the first 600 frames and every 50th with --quick), and the EXTRA FILES
(native or benchmark CSV).

Writes DIR/certificate.json and DIR/certificate.md: counts, seed, the CGAL and
GMP versions and the git commit. On any violation the first violating case is
saved in DIR as a corpus file (a .vf query, or an .obj for a tree), named in
the output, and the exit status is 1.

  --quick          200 queries per family and 30 soup pairs: under a minute
  --out DIR        where the certificate goes (default: certificate)
  --corpus DIR     the corpus folder (default: corpus)
  --seed S         seed of the fuzzed queries and soups (default 1)
  --per-family N   fuzzed queries per family (default 3000; 200 with --quick)
  --soups N        soup pairs (default 300; 30 with --quick)
  -h, --help       this text
)";

}  // namespace

bool read_certify_option(ArgReader& a, CertifyOptions& opt) {
  if (a.is("--quick")) {
    opt.quick = true;
  } else if (a.is("--out")) {
    opt.out_dir = a.value();
  } else if (a.is("--corpus")) {
    opt.corpus_dir = a.value();
  } else if (a.is("--seed")) {
    opt.seed = std::uint64_t(a.integer(0, 1LL << 40));
  } else if (a.is("--per-family")) {
    opt.per_family = long(a.integer(0, 1LL << 30));
  } else if (a.is("--soups")) {
    opt.soups = long(a.integer(0, 1LL << 30));
  } else if (!a.is_option()) {
    opt.extra_files.push_back(a.word());
  } else {
    return false;
  }
  return true;
}

int certify_command(const Args& args, std::ostream& out, std::ostream& err) {
  CertifyOptions opt;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kCertifyHelp;
      return 0;
    } else if (!read_certify_option(a, opt)) {
      a.unknown("certify");
    }
  }
  const Certificate c = certify(opt);
  write_certificate(c);
  const std::filesystem::path dir(opt.out_dir);

  long checks = c.static_queries + c.moving_queries + c.truths,
       violations = c.robust_violations + c.moving_violations + c.truth_violations;
  for (std::size_t i = 0; i < kCertifiedK.size(); ++i) {
    checks += c.boxes[i] + c.soup_pairs[i];
    violations += c.box_violations[i] + c.cull_violations[i];
  }
  out << (c.certified() ? "certified" : "VIOLATED") << ": " << checks << " checks, " << violations
      << " violations (" << c.corpus_queries << " corpus, " << c.fuzzed_queries << " fuzzed, "
      << c.scene_queries << " scene, " << c.extra_queries << " extra queries; " << c.options.soups
      << " soup pairs); wrote " << (dir / "certificate.md").string() << " and .json\n";
  if (!c.certified()) {
    err << "fdhcert: certify: " << c.first_violation << "\n";
    return 1;
  }
  return 0;
}

}  // namespace fdh::verify

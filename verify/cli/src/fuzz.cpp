// fdhcert fuzz: find, shrink and store cases where a method disagrees with exact.
#include <unistd.h>

#include <cstdio>

#include "commands.hpp"
#include "fdh/suite/fuzz.hpp"
#include "fdh/io/json.hpp"

namespace fdh::verify {
namespace {

const char* const kFuzzHelp =
    R"(usage: fdhcert fuzz --method M --family F --out DIR [--seed S] [--count N]
                    [--shard I/N] [--threads T] [--chunk N] [--json]

Draws N queries from generator family F and runs method M and exact on each.
Every disagreement is shrunk (RapidCheck's shrink tree, greedy) to a minimal
case; distinct cases are written to DIR/M/F/<hash>.vf in the native format,
with exact's verdict as the truth and a comment saying what M answered.

  --method M       exact, robust, paper-literal, paper-intended, linear-system
  --family F       parallel-cross, parallel-short, parallel-land, parallel-start,
                   angled, through-edge, through-vertex, hair-outside-edge,
                   in-plane, zero-motion, grazing, far-from-origin, tiny, sliver,
                   degenerate
  --out DIR        where the cases go (created if needed)
  --seed S         run seed (default 1); case i is drawn from seed (S, i)
  --count N        cases in the whole run, all shards together (default 10000)
  --shard I/N      run only shard I of N (1 <= I <= N): cases
                   [(I-1)N'/N, I N'/N) of the N' cases. The shards of one seed
                   together are exactly the unsharded run; merge them by
                   copying their DIRs into one (file names are content hashes)
  --threads T      worker processes (default: every core)
  --chunk N        cases per checkpoint step (default 500)
  --json           print the summary as one JSON object
  -h, --help       this text

The same seed and shard always give the same cases. Progress is saved after
every chunk of cases, in DIR/.fuzz/: a run that is killed and started again
with the same arguments continues where it stopped, losing no case. On a
terminal, a progress line shows cases done, rate and cases found.
)";

}  // namespace

int fuzz_command(const Args& args, std::ostream& out, std::ostream& err) {
  FuzzOptions opt;
  bool json = false, have_family = false;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kFuzzHelp;
      return 0;
    } else if (a.is("--method")) {
      opt.method = a.value();
    } else if (a.is("--family")) {
      const std::string& f = a.value();
      const auto fam = family_by_name(f);
      if (!fam) throw UsageError("unknown family '" + f + "' (see fdhcert fuzz --help)");
      opt.family = *fam;
      have_family = true;
    } else if (a.is("--out")) {
      opt.out_dir = a.value();
    } else if (a.is("--seed")) {
      opt.seed = std::uint64_t(a.integer(0, (1LL << 62)));
    } else if (a.is("--count")) {
      opt.count = long(a.integer(0, 1LL << 40));
    } else if (a.is("--threads")) {
      opt.threads = int(a.integer(1, 1024));
    } else if (a.is("--shard")) {
      const std::string& v = a.value();
      int i = 0, n = 0;
      char slash = 0, extra = 0;
      if (std::sscanf(v.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' ||
          n < 1 || i < 1 || i > n)
        throw UsageError("--shard takes I/N with 1 <= I <= N, not '" + v + "'");
      opt.shard = i - 1;
      opt.shards = n;
    } else if (a.is("--json")) {
      json = true;
    } else if (a.is("--chunk")) {
      opt.chunk = int(a.integer(1, 1 << 20));
    } else {
      a.unknown("fuzz");
    }
  }
  if (opt.method.empty()) throw UsageError("fuzz needs --method");
  if (!have_family) throw UsageError("fuzz needs --family");
  if (opt.out_dir.empty()) throw UsageError("fuzz needs --out DIR");
  opt.progress = ::isatty(2) && !json;

  FuzzSummary s;
  try {
    s = run_fuzz(opt, err);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const std::string family = family_name(opt.family);
  if (json) {
    out << "{\"method\": " << json_string(opt.method) << ", \"family\": \"" << family
        << "\", \"seed\": " << opt.seed << ", \"shard\": \"" << opt.shard + 1 << "/" << opt.shards
        << "\", \"first\": " << s.first << ", \"last\": " << s.last << ", \"cases\": " << s.cases
        << ", \"resumed\": " << s.resumed << ", \"disagreements\": " << s.disagreements
        << ", \"distinct\": " << s.distinct.size() << ", \"files\": [";
    bool first = true;
    for (const std::string& f : s.distinct) {
      out << (first ? "" : ", ") << json_string(f);
      first = false;
    }
    out << "]}\n";
  } else {
    out << "fuzz " << opt.method << " on " << family << ", seed " << opt.seed << ", cases "
        << s.first << ".." << s.last - 1 << " (shard " << opt.shard + 1 << "/" << opt.shards
        << ")\n"
        << s.cases << " cases (" << s.resumed << " done by an earlier run), " << s.disagreements
        << " disagreements with exact, " << s.distinct.size() << " distinct shrunk cases\n";
    for (const std::string& f : s.distinct) out << "  " << f << "\n";
  }
  return 0;
}

}  // namespace fdh::verify

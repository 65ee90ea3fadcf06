// fdhcert generate: a file of queries from one generator family, for classify and benchmarks
// (for instance robust against float-cubic on generic moving queries).
#include <sstream>

#include "commands.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/gen/static_families.hpp"
#include "fdh/suite/fuzz.hpp"
#include "fdh/gen/moving_families.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

const char* const kGenerateHelp =
    R"(usage: fdhcert generate FAMILY --out FILE [--count N] [--seed S]

Writes N queries (default 10000) of a generator family to FILE in the native
format, with the truth where the construction knows it. Case i comes from the
seed (S, i), as in fuzz: the same seed gives the same file.

FAMILY is a static vertex-face family (the 15 of fuzz --help, e.g. angled) or
a moving one: random-linear, generic-moving, rotating, hourglass, two-crossings, coplanar,
sliding-on-edge, parallel-edges, degenerate-edge. generic-moving is the
generic case (full-precision random coordinates, no exact coincidence);
random-linear uses small integers, so it is full of exact ties.

Then, for example:
  fdhcert classify FILE --methods exact,robust,float-cubic
)";

}  // namespace

int generate_command(const Args& args, std::ostream& out, std::ostream&) {
  std::string family, file;
  long count = 10000;
  std::uint64_t seed = 1;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kGenerateHelp;
      return 0;
    } else if (a.is("--out")) {
      file = a.value();
    } else if (a.is("--count")) {
      count = long(a.integer(1, 100000000));
    } else if (a.is("--seed")) {
      seed = std::uint64_t(a.integer(0, (1LL << 62)));
    } else if (a.is_option()) {
      a.unknown("generate");
    } else if (family.empty()) {
      family = a.word();
    } else {
      throw UsageError("generate takes one family, not '" + a.word() + "' too");
    }
  }
  if (family.empty()) throw UsageError("generate needs a family (see fdhcert generate --help)");
  if (file.empty()) throw UsageError("generate needs --out FILE");
  const auto fixed = family_by_name(family);
  const auto moving = moving_family_by_name(family);
  if (!fixed && !moving) throw UsageError("unknown family '" + family + "' (see --help)");
  std::string text = "# fdhcert generate " + family + " --count " + std::to_string(count) +
                     " --seed " + std::to_string(seed) + "\n";
  std::ostringstream os;
  for (long i = 0; i < count; ++i) {
    const rc::Random random(case_seed(seed, i));
    Query q = fixed ? gen_family(*fixed)(random).value().query
                    : gen_moving(*moving)(random).value().query;
    q.id = family + "/" + std::to_string(i);
    write_native(os, q);
  }
  write_file_atomically(file, text + os.str());
  out << "wrote " << count << " " << family << " queries to " << file << "\n";
  return 0;
}

}  // namespace fdh::verify

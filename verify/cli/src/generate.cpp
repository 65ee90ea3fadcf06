// fdhcert generate: a file of queries from one generator family, for classify and benchmarks
// (for instance robust against float-cubic on generic moving queries).
#include <memory>

#include "commands.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/gen/family_file.hpp"

namespace fdh::verify {
namespace {

const char* const kGenerateAbout =
    R"(write queries of a generator family to a file

Writes N queries (default 10000) of a generator family to FILE in the native
format, with the truth where the construction knows it. Case i comes from the
seed (S, i), as in fuzz: the same seed gives the same file.)";

const char* const kGenerateFooter =
    R"(FAMILY is a static vertex-face family (the 15 of fuzz --help, e.g. angled) or
a moving one: random-linear, generic-moving, rotating, hourglass, two-crossings,
coplanar, sliding-on-edge, parallel-edges, degenerate-edge. generic-moving is
the generic case (full-precision random coordinates, no exact coincidence);
random-linear uses small integers, so it is full of exact ties.

Then, for example:
  fdhcert classify FILE --methods exact,robust,float-cubic)";

struct GenerateOptions {
  std::string family, file;
  long count = 10000;
  std::uint64_t seed = 1;
};

int run_generate(const GenerateOptions& o, const Io& io) {
  check_output_path(o.file);
  write_family_file(o.family, o.count, o.seed, o.file);  // the family checked by CLI11
  io.out << "wrote " << o.count << " " << o.family << " queries to " << o.file << "\n";
  return 0;
}

}  // namespace

Command add_generate(CLI::App& app) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = add_command(app, "generate", kGenerateAbout, kGenerateFooter);
  std::vector<std::string> families;
  for (const Family& f : all_families()) families.push_back(f.name);
  for (const Family& f : delta_families()) families.push_back(f.name);
  cmd->add_option("FAMILY", o->family, "a generator family (below)")
      ->required()
      ->check(one_of(families));
  cmd->add_option("--out", o->file, "the file to write")->required()->type_name("FILE");
  add_number_option(*cmd, "--count", o->count, "queries to write (default 10000)", "N", 1L,
                    kMaxGeneratedQueries);
  add_seed_option(*cmd, o->seed, "the run's seed (default 1)");
  return {cmd, [o](const Io& io) { return run_generate(*o, io); }};
}

}  // namespace fdh::verify

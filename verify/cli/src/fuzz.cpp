// fdhcert fuzz: find, shrink and store cases where a method disagrees with exact.
#include <nlohmann/json.hpp>

#include <memory>

#include "commands.hpp"
#include "fdh/fuzz/fuzz.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/os/atomic_file.hpp"
#include "min_distance_option.hpp"

namespace fdh::verify {
namespace {

const char* const kFuzzAbout =
    R"(search a generator family for cases where a method is wrong

Draws N queries from generator family F (static or moving, vertex-face or
edge-edge) and checks method M against the exact twin on each it applies to.
Every disagreement is shrunk to a minimal case: RapidCheck's shrink tree, then
a greedy pass that stops motion, moves the case toward the origin and
shortens coordinates while M still fails in the same direction (a false alarm
stays a false alarm, a miss a miss) on a query of the same kind (static,
moving vertex-face or edge-edge, as drawn, no triangle or edge drawn whole
collapsed to a point). Distinct cases are written to
DIR/M/F/<direction>-<hash>.vf (direction fp: a false alarm, fn: a miss) in
the native format, with the twin's verdict as the truth and a comment saying
what M answered, the exact contact (its time, for a moving query) and the
direction. The summary counts the disagreements by direction.

With --metamorphic it looks instead for queries where M's verdict changes
under a transform that keeps the truth (time reversal, axis order, mirror,
dyadic translation or velocity, power-of-two scale, relabelled corners or
ends; docs/methods.md): no oracle needed, so any method, the exact twin
included. A method with a promise (conservative or exact) is also judged on
each transform against the twin's verdict, which the transforms keep: a
broken promise there is found first. Such a query is shrunk while some
transform still breaks M's promise (or changes its verdict), and stored in
DIR/metamorphic/M/F/<hash>.vf with the twin's verdict as the truth and a
comment naming the transform and both verdicts, or the promise broken.

With --toi (moving families only) it checks M's time of impact instead: a
finding is a contact missed, a time after the exact earliest contact t*
(late), one that breaks M's time promise otherwise, or one earlier than t* by
more than --toi-tolerance of the step. Each is shrunk while M's time stays in
the same class (a late case stays late) and stored in
DIR/toi/M/F/<class>-<hash>.vf (class: missed, late, broken, early) with the
twin's verdict as the truth and a comment giving M's enclosure and the exact
contact time.)";

const char* const kFuzzFooter =
    R"(The same seed and shard always give the same cases. Progress is saved in
DIR/.fuzz/ as cases are done: a run killed and started again with the same
--method, --family, --seed, --count, --shard, --metamorphic, --min-distance
and --toi (with its --width and --toi-tolerance; any --chunk and --threads)
continues where it stopped and ends with exactly the cases of an uninterrupted
run. A second run on DIR while one runs, or a run with other options while DIR
holds an unfinished run, stops with exit status 2. On a terminal, a progress
line shows cases done, rate and cases found.)";

struct FuzzCommandOptions {
  FuzzOptions run;
  std::string shard;  // "I/N"
  bool json = false;
  ProgressWhen progress = ProgressWhen::Auto;
};

std::vector<std::string> every_family_name() {
  std::vector<std::string> names;
  for (const Family& f : all_families()) names.push_back(f.name);
  for (const Family& f : delta_families()) names.push_back(f.name);
  return names;
}

// D as %.17g: the same double when read back.
std::string round_trip_text(double d) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", d);
  return text;
}

// "a, b, c" broken into lines of at most `width` characters.
std::string wrapped(const std::vector<std::string>& words, std::size_t width) {
  std::string out, line;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string w = words[i] + (i + 1 < words.size() ? "," : "");
    if (!line.empty() && line.size() + 1 + w.size() > width) out += line + "\n", line.clear();
    line += (line.empty() ? "" : " ") + w;
  }
  return out + line;
}

// The raw findings by direction, every class of the mode named (0 included): "971 FP (false
// alarms), 1029 FN (misses)", or with --toi "1 missed, 2 late, 0 broken, 3 early". Cases of a
// run resumed from before classes were named are added as "N unclassed".
std::string by_direction(const FuzzOptions& opt, const FuzzSummary& s) {
  const auto n = [&s](const char* c) {
    const auto it = s.by_class.find(c);
    return std::to_string(it == s.by_class.end() ? 0 : it->second);
  };
  std::string text = opt.toi ? n("missed") + " missed, " + n("late") + " late, " + n("broken") +
                                   " broken, " + n("early") + " early"
                             : n("fp") + " FP (false alarms), " + n("fn") + " FN (misses)";
  if (s.by_class.count("disagrees")) text += ", " + n("disagrees") + " unclassed";
  return text;
}

void print_summary(const FuzzOptions& opt, const FuzzSummary& s, bool json, std::ostream& out) {
  const std::string shard = std::to_string(opt.shard + 1) + "/" + std::to_string(opt.shards);
  if (json) {
    nlohmann::ordered_json j = {{"method", opt.method},
                                {"metamorphic", opt.metamorphic},
                                {"toi", opt.toi},
                                {"family", opt.family},
                                {"seed", opt.seed},
                                {"shard", shard},
                                {"first", s.first},
                                {"last", s.last},
                                {"cases", s.cases},
                                {"resumed", s.resumed},
                                {"disagreements", s.disagreements},
                                {"by_direction", s.by_class},
                                {"distinct", s.distinct.size()},
                                {"files", s.distinct}};
    if (opt.min_distance > 0) j["min_distance"] = opt.min_distance;
    if (opt.budget.limited()) j["cut_by_budget"] = s.cut, j["shrinking_cut"] = s.shrink_cut;
    print_json(out, j);
    return;
  }
  const char* found = opt.metamorphic ? " verdicts changed by a transform, "
                      : opt.toi       ? " TOI findings, "
                                      : " disagreements with exact, ";
  out << "fuzz "
      << (opt.metamorphic ? "--metamorphic "
          : opt.toi       ? "--toi "
                          : "")
      << opt.method << " on " << opt.family
      << (opt.min_distance > 0 ? " at min-distance " + round_trip_text(opt.min_distance) : "")
      << ", seed " << opt.seed << ", cases " << s.first << ".." << s.last - 1 << " (shard " << shard
      << ")\n"
      << s.cases << " cases (" << s.resumed << " done by an earlier run), " << s.disagreements
      << found << s.distinct.size() << " distinct shrunk cases\n";
  if (!opt.metamorphic) out << opt.method << " by direction: " << by_direction(opt, s) << "\n";
  for (const std::string& f : s.distinct) out << "  " << f << "\n";
  if (s.cut)
    out << "budget of " << opt.budget.seconds() << " s spent: stopped after " << s.cases << " of "
        << s.last - s.first << " cases; the same command resumes the rest\n";
  if (s.shrink_cut)
    out << "shrinking: the budget stopped it on " << s.shrink_cut
        << " case(s), stored as far as they shrank\n";
}

int run_fuzz_command(FuzzCommandOptions& o, const Io& io) {
  FuzzOptions& opt = o.run;
  check_output_dir(opt.out_dir);
  if (!o.shard.empty()) {
    const auto [shard, shards] = i_of_n(o.shard);  // checked by i_of_n_validator
    opt.shard = shard - 1;
    opt.shards = shards;
  }
  ProgressLine progress(
      io.err, progress_wanted(io, o.json && o.progress == ProgressWhen::Auto ? ProgressWhen::Never
                                                                             : o.progress));
  opt.progress = progress.sink();
  FuzzSummary s;
  try {
    s = run_fuzz(opt);
    progress.clear();
  } catch (const std::invalid_argument& e) {  // an unknown method
    throw UsageError(e.what());
  }
  print_summary(opt, s, o.json, io.out);
  return 0;
}

}  // namespace

Command add_fuzz(CLI::App& app) {
  auto o = std::make_shared<FuzzCommandOptions>();
  FuzzOptions& opt = o->run;
  CLI::App* cmd = add_command(app, "fuzz", kFuzzAbout, kFuzzFooter);
  cmd->add_option("--method", opt.method,
                  wrapped(method_names(), 56) + "\n(a --plugin FILE adds its methods)")
      ->required()
      ->type_name("M");
  cmd->add_option("--family", opt.family, wrapped(every_family_name(), 56))
      ->required()
      ->type_name("F")
      ->check(one_of(every_family_name()));
  cmd->add_option("--out", opt.out_dir, "where the cases go (created if needed)")
      ->required()
      ->type_name("DIR");
  add_seed_option(*cmd, opt.seed, "run seed (default 1); case i is drawn from seed (S, i)");
  cmd->add_option("--count", opt.count,
                  "cases in the whole run, all shards together (default\n10000; at most 10^12)")
      ->type_name("N")
      ->check(CLI::Range(0L, kMaxFuzzCount));
  cmd->add_option("--shard", o->shard,
                  "run only shard I of N (1 <= I <= N <= 10^6): cases\n"
                  "[(I-1)N'/N, I N'/N) of the N' cases. The shards of one seed\n"
                  "together are exactly the unsharded run; merge them by\n"
                  "copying their DIRs into one (file names are content hashes)")
      ->type_name("I/N")
      ->check(i_of_n_validator(kMaxFuzzShards));
  cmd->add_option("--threads", opt.threads, "worker processes (default: every core)")
      ->type_name("T")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--chunk", opt.chunk,
                  "cases per checkpoint step (default 500); may differ when resuming")
      ->type_name("N")
      ->check(CLI::Range(1, 1 << 20));
  add_plugin_option(*cmd);
  add_budget_option(*cmd, opt.budget, "the workers and shrinking");
  cmd->add_flag("--metamorphic", opt.metamorphic,
                "look for verdicts that change under a truth-keeping\ntransform (above)");
  CLI::Option* toi = cmd->add_flag("--toi", opt.toi,
                                   "look for late, promise-breaking or too early times\n"
                                   "of impact on a moving family (above)");
  toi->excludes("--metamorphic");
  cmd->add_option("--width", opt.toi_width,
                  "with --toi: the enclosure width asked of each time, in\n"
                  "[2^-52, 1] steps (default 2^-30; 2^-N is taken)")
      ->type_name("W")
      ->transform(real_range(0x1p-52, 1.0, "[2^-52, 1]"))
      ->needs(toi);
  cmd->add_option("--toi-tolerance", opt.toi_tolerance,
                  "with --toi: how early (t* - t_lo, in steps) a time may be\n"
                  "before it is a finding, T in [0, 1] (default 0.1)")
      ->type_name("T")
      ->transform(real_range(0.0, 1.0, "[0, 1]"))
      ->needs(toi);
  add_min_distance_option(*cmd, opt.min_distance,
                          "ask every case at minimum separation D (a hit: within\n"
                          "distance D at some time) instead of each case's own\n"
                          "(contact, or a delta- family's D); the case files carry D");
  cmd->add_flag("--json", o->json, "print the summary as one JSON object");
  add_quiet_flag(*cmd, o->progress);
  return {cmd, [o](const Io& io) { return run_fuzz_command(*o, io); }};
}

}  // namespace fdh::verify

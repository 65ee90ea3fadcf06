// fdhcert replay: re-run stored cases; exact must still give each stored truth.
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "commands.hpp"
#include "fdh/classify/replay.hpp"
#include "min_distance_option.hpp"

namespace fdh::verify {
namespace {

const char* const kReplayAbout =
    R"(re-run stored cases: which methods still fail where

Re-runs stored cases of every kind: static and moving vertex-face, edge-edge
(native query files; a folder means every *.vf below it, such as corpus/ or a
fuzz --out folder). Every case must carry a truth.

  exact must still give each case's stored truth: if it does not, replay names
  the case and exits with status 1.
  For every other method it reports which cases it still gets wrong (a case
  it makes no decision on is not counted).
  With --toi, also the cases where a method's time of impact is late (a
  contact missed, or t_lo after the exact earliest contact) or 0 where the
  contact is later, and those earlier than the exact contact by more than
  --toi-tolerance of the step (fuzz --toi's early findings).)";

const char* const kReplayFooter =
    R"(--json prints {"cases": N, "exact_mismatches": [...],
               "methods": {"<name>": {"failing": K, "cases": [...]}}}
and with --toi also "toi": {"<name>": {"late": [...], "zero": [...],
                                       "early": [...], "broken": [...]}}
(broken: the cases where the time breaks the method's time promise), and with
--min-distance D > 0 also "min_distance": D.)";

struct ReplayCli {
  ReplayOptions job;
  bool json = false;
};

int run_replay(const ReplayCli& o, const Io& io) {
  ReplayResult r;
  try {
    r = replay_job(o.job);
  } catch (const std::invalid_argument& e) {  // the options, checked by the job
    throw UsageError(e.what());
  }
  if (o.json)
    print_json(io.out, r.to_json());
  else
    io.out << r.text();
  for (const std::string& w : r.twin_mismatches)
    io.err << "fdhcert: exact no longer gives the stored truth at " << w << "\n";
  return r.twin_mismatches.empty() ? 0 : 1;
}

}  // namespace

Command add_replay(CLI::App& app) {
  auto cli = std::make_shared<ReplayCli>();
  ReplayOptions* o = &cli->job;
  CLI::App* cmd = add_command(app, "replay", kReplayAbout, kReplayFooter);
  cmd->add_option("PATH", o->paths, "a case file, or a folder of them")->required();
  add_methods_option(*cmd, o->methods, "comma-separated methods (default: all)");
  add_plugin_option(*cmd);
  cmd->add_flag("--json", cli->json, "print one JSON object (below)");
  CLI::Option* toi = cmd->add_flag("--toi", o->toi,
                                   "also re-check every method's time of impact: the cases\n"
                                   "where it is late, 0, or breaks its time promise");
  cmd->add_option("--width", o->width,
                  "with --toi: the enclosure width asked of each time, in\n"
                  "[2^-52, 1] steps (default 2^-30; 2^-N is taken)")
      ->type_name("W")
      ->transform(real_range(0x1p-52, 1.0, "[2^-52, 1]"))
      ->needs(toi);
  cmd->add_option("--toi-tolerance", o->tolerance,
                  "with --toi: list a time as early when t* - t_lo exceeds\n"
                  "T steps, T in [0, 1] (default 0.1, as fuzz --toi)")
      ->type_name("T")
      ->transform(real_range(0.0, 1.0, "[0, 1]"))
      ->needs(toi);
  add_min_distance_option(*cmd, o->min_distance,
                          "ask every case at minimum separation D (default 0:\n"
                          "contact); a stored truth counts only where the case's D\n"
                          "is this D; methods that answer contact only are not counted");
  return {cmd, [cli](const Io& io) { return run_replay(*cli, io); }};
}

}  // namespace fdh::verify

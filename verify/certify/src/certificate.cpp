// certificate.json and certificate.md: a Certificate for programs and for people.
#include <fmt/format.h>

#include <filesystem>
#include <iterator>
#include <nlohmann/json.hpp>

#include "fdh/certify/certify.hpp"
#include "fdh/classify/toi_report.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using Out = std::back_insert_iterator<fmt::memory_buffer>;

// What a method's time promise says, against the exact earliest contact t*.
const char* time_promise_words(TimePromise p) {
  switch (p) {
    case TimePromise::Enclosure:
      return "encloses the exact earliest contact t* within the width, exact verdict";
    case TimePromise::NeverLate:
      return "is never later than the exact earliest contact t*, misses no contact";
    case TimePromise::None:
      return "against the exact earliest contact t*";
  }
  return "";
}

// What a method's promise says about its verdicts, against the exact twin.
const char* promise_words(Promise p) {
  switch (p) {
    case Promise::Exact:
      return "= the exact twin";
    case Promise::Conservative:
      return "misses no hit of the exact twin";
    case Promise::None:
      return "against the exact twin";
  }
  return "";
}

void inputs_markdown(Out to, const Certificate& c) {
  fmt::format_to(to, "## Inputs\n\n| source | queries |\n|---|---|\n");
  fmt::format_to(to, "| corpus (`{}`, {} files) | {} |\n", c.options.corpus_dir, c.corpus_files,
                 c.corpus_queries);
  fmt::format_to(to, "| fuzzed: {} per family, {} static and {} moving families | {} |\n",
                 c.options.per_family, c.families.size(), c.moving_families.size(),
                 c.fuzzed_queries);
  fmt::format_to(to, "| extra files ({}) | {} |\n", c.options.extra_files.size(), c.extra_queries);
  fmt::format_to(to,
                 "| narrow-phase queries recorded from the shipped scenes ({} scenes, robust, "
                 "every {}th frame) | {} |\n",
                 c.scenes, c.options.scene_stride, c.scene_queries);
  fmt::format_to(to, "| random triangle-soup pairs (tree) | {} |\n\n", c.options.soups);
}

// " (q.vf:1, 'gen', ...)": the first queries of the zero times, where there are any.
std::string zero_names(const TimePromiseCheck& p) {
  std::string named;
  for (const std::string& z : p.zero_queries) named += (named.empty() ? "" : ", ") + z;
  if (named.empty()) return "";
  return " (" + named + (p.tally.zero > long(p.zero_queries.size()) ? ", ...)" : ")");
}

// "2 not a time, 1 no answer in time, " where a plug-in gave such times (each a violation).
std::string faults_words(const TimeTally& t) {
  return (t.garbage ? fmt::format("{} not a time, ", t.garbage) : "") +
         (t.no_answer ? fmt::format("{} no answer in time, ", t.no_answer) : "");
}

void promise_rows(Out to, const std::vector<PromiseCheck>& promises,
                  const std::vector<TimePromiseCheck>& times) {
  for (const PromiseCheck& p : promises)
    fmt::format_to(
        to, "| {} verdict {} | `{}` | – | {} queries{} | {} |\n", to_string(p.decision),
        promise_words(p.promise), p.method, p.checked,
        (p.filter_decided ? fmt::format(" ({} decided by the float filter alone)", p.filter_decided)
                          : std::string()) +
            (p.no_answer ? fmt::format(" ({} no answer in time)", p.no_answer) : ""),
        p.violations);
  for (const TimePromiseCheck& p : times)
    fmt::format_to(to,
                   "| {} time {} | `{}` | – | {} queries ({} contacts; {} late, {} zero{}, {}"
                   "earliest by {:.3g} of the step, median {:.3g}) | {} |\n",
                   to_string(p.decision), time_promise_words(p.promise), p.method, p.tally.checked,
                   p.tally.contacts, p.tally.late, p.tally.zero, zero_names(p),
                   faults_words(p.tally), p.tally.early_max(), p.tally.early_median(),
                   p.tally.broken);
}

void properties_markdown(Out to, const Certificate& c) {
  fmt::format_to(to,
                 "## Properties\n\n| property | method | k | checked | violations |\n"
                 "|---|---|---|---|---|\n");
  for (const BoxCheck& b : c.boxes)
    fmt::format_to(to, "| float FDH contains the exact FDH | `{}` | {} | {} boxes | {} |\n",
                   b.method, b.k, b.boxes, b.box_violations);
  for (const BoxCheck& b : c.boxes) {
    if (!b.tree) continue;  // a plug-in's boxes: fast/'s tree is not made of them
    fmt::format_to(to,
                   "| tree traversal finds every exactly overlapping pair | `{}` | {} | {} tree "
                   "pairs, {} overlapping primitive pairs | {} |\n",
                   b.method, b.k, b.soup_pairs, b.exact_pairs, b.cull_violations);
  }
  promise_rows(to, c.promises, c.times);
  fmt::format_to(to,
                 "| the exact twin = the known truth (corpus and benchmark files; fuzzed queries "
                 "whose construction fixes it) | – | – | {} queries | {} |\n",
                 c.truths, c.truth_violations);
}

void metamorphic_rows(Out to, const std::vector<MetamorphicCheck>& rows) {
  for (const MetamorphicCheck& m : rows)
    fmt::format_to(to, "| `{}` | {} | {} | {} | {} | {} |\n", m.method, to_string(m.promise),
                   m.checked, m.violations, m.judged, m.broken);
}

// Every method under the truth-keeping transforms: promised methods must change no verdict.
void metamorphic_markdown(Out to, const Certificate& c) {
  fmt::format_to(
      to,
      "\n## Metamorphic checks\n\nEvery query above under each transform that keeps "
      "its truth (docs/methods.md, \"Metamorphic checks\"): a changed verdict is wrong "
      "on one of the two queries. Methods that promise the exact verdict must change "
      "none (a violation); the others are counted. Every method with a promise (the twin "
      "aside) is also judged on each transformed query against the exact verdict of the "
      "query, which the transforms keep: a broken promise is a violation.\n\n"
      "| method | promise | transformed queries | verdicts changed | judged against the "
      "promise | promise broken |\n|---|---|---|---|---|---|\n");
  metamorphic_rows(to, c.metamorphic);
  fmt::format_to(to,
                 "\nEach transform applies only where it is exact: a query where a coordinate "
                 "would round, overflow or leave the normal range is skipped.\n\n"
                 "| transform | queries transformed | skipped as inexact |\n|---|---|---|\n");
  for (const TransformCount& t : c.metamorphic_transforms)
    fmt::format_to(to, "| `{}` | {} | {} |\n", t.transform, t.applied, t.skipped);
}

// 180000 as "180,000".
std::string grouped(long n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return (n < 0 ? "-" : "") + out;
}

// The δ promise lines and the δ metamorphic counts.
void delta_markdown(Out to, const Certificate& c) {
  const DeltaStage& d = c.delta;
  if (!d.run) return;
  fmt::format_to(to,
                 "\n## Minimum separation\n\nThe methods that answer the minimum-separation "
                 "question (within distance δ at some time of the step; docs/methods.md) against "
                 "the exact δ twin, at δ = {}: {} queries of the {} delta- families (each at its "
                 "own δ), and {} contact queries (every 8th of the corpus and of each family's "
                 "first cases) asked again at δ.\n\n| property | method | k | checked | "
                 "violations |\n|---|---|---|---|---|\n",
                 d.delta_words(), d.family_queries, d.families.size(), d.contact_queries);
  promise_rows(to, d.promises, d.times);
  fmt::format_to(to,
                 "| the exact twin = the known truth (the delta- families' constructions) | – | "
                 "– | {} queries | {} |\n\nUnder the metamorphic transforms (the scales scale "
                 "δ with the query):\n\n| method | promise | transformed queries | verdicts "
                 "changed | judged against the promise | promise broken |\n"
                 "|---|---|---|---|---|---|\n",
                 d.truths, d.truth_violations);
  metamorphic_rows(to, d.metamorphic);
}

// The first words: certified, violated, or cut short by the budget (which certifies nothing).
std::string verdict_markdown(const Certificate& c) {
  if (!c.first_violation.empty()) {  // the first, then every kind of broken promise found
    std::string all;
    for (const std::string& b : c.broken_saved) all += "\n- " + b + ".";
    return fmt::format("**Violated**: {}.", c.first_violation) +
           (c.broken_saved.size() < 2 ? ""
                                      : fmt::format("\n\n{} kinds of broken promise, each saved "
                                                    "with its first case:\n{}",
                                                    c.broken_saved.size(), all));
  }
  if (c.complete()) return "**Certified**: no violation.";
  std::string cuts;
  for (const BudgetCut& cut : c.cut_short) cuts += (cuts.empty() ? "" : "; ") + cut_words(cut);
  return fmt::format(
      "**Not certified: cut short by the budget** (`--budget {}`): no violation in what was "
      "checked, but the run stopped before its end, so this is not a certification. Cut short: "
      "{}.",
      c.options.budget.seconds(), cuts);
}

void plugins_markdown(Out to, const Certificate& c) {
  if (c.options.plugins.empty()) return;
  fmt::format_to(to,
                 "## Plug-ins\n\n| method | file | settings | thread-safe |\n|---|---|---|---|\n");
  for (const CertifiedPlugin& p : c.options.plugins) {
    std::string settings;
    for (const auto& [key, value] : p.settings)
      settings += (settings.empty() ? "" : ", ") + ("`" + key + "=" + printable(value) + "`");
    fmt::format_to(to, "| `{}` | `{}` | {} | {} |\n", p.name, printable(p.file),
                   settings.empty() ? "none" : settings, p.thread_safe ? "yes" : "no");
  }
  fmt::format_to(to, "\n");
}

}  // namespace

std::string cut_words(const BudgetCut& cut) {
  if (cut.done == 0 && cut.total == 0) return cut.stage + ": not run";
  if (cut.total <= 0)
    return fmt::format("{}: {} {} checked", cut.stage, grouped(cut.done), cut.unit);
  return fmt::format("{}: {} of {} {}", cut.stage, grouped(cut.done), grouped(cut.total), cut.unit);
}

long Certificate::checks() const {
  long n = truths + delta.checks();
  for (const PromiseCheck& p : promises) n += p.checked;
  for (const TimePromiseCheck& p : times) n += p.tally.checked;
  for (const BoxCheck& b : boxes) n += b.boxes + b.soup_pairs;
  for (const MetamorphicCheck& m : metamorphic) n += (m.held() ? m.checked : 0) + m.judged;
  return n;
}

long Certificate::violations() const {
  long n = truth_violations + delta.violations();
  for (const PromiseCheck& p : promises) n += p.violations;
  for (const TimePromiseCheck& p : times) n += p.tally.broken;
  for (const BoxCheck& b : boxes) n += b.box_violations + b.cull_violations;
  for (const MetamorphicCheck& m : metamorphic) n += (m.held() ? m.violations : 0) + m.broken;
  return n;
}

std::vector<std::string> certify_outputs() {
  return {"certificate.json", "certificate.md", "violation-*", "peers"};
}

void write_certificate(const Certificate& c) {
  const fs::path dir(c.options.files_dir());
  write_file_atomically((dir / "certificate.json").string(), certificate_json(c));
  write_file_atomically((dir / "certificate.md").string(), certificate_markdown(c));
}

std::string certificate_markdown(const Certificate& c) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to, "# fdhcert certificate\n\n{}\n", verdict_markdown(c));
  std::string stages;  // the stages given, when not all in the default order
  for (const std::string& s : c.options.stages) stages += (stages.empty() ? " --stages " : ",") + s;
  fmt::format_to(
      to, "\nCommit `{}`, CGAL {}, GMP {}, {} run, seed {}. Made by `fdhcert certify{}{}`.\n\n",
      c.commit, c.cgal, c.gmp, c.mode(), c.options.seed, c.options.quick ? " --quick" : "", stages);
  plugins_markdown(to, c);
  inputs_markdown(to, c);
  properties_markdown(to, c);
  metamorphic_markdown(to, c);
  delta_markdown(to, c);
  fmt::format_to(to, "\n{}", peers_markdown(c.peers));
  return fmt::to_string(out);
}

}  // namespace fdh::verify

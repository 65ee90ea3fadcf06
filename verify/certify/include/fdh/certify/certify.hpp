// fdhcert certify: checks the fast library against the exact reference on the corpus, fuzzed
// cases of every family (static and moving), queries recorded from the shipped cloth scenes,
// random triangle soups and any extra query files, and counts each certified property.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/os/budget.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/peer_certify/peer_certify.hpp"

namespace fdh::verify {

// A plug-in the run loaded (docs/plugins.md), as the certificate records it: its file, its
// method name, the settings given to its fdh_plugin_init and whether it declared itself
// thread-safe.
struct CertifiedPlugin {
  std::string file, name;
  std::vector<std::pair<std::string, std::string>> settings;
  bool thread_safe = false;
  bool probe_cut = false;  // --budget ended its start-up probe, after probe_calls calls
  long probe_calls = 0;
};

// The stages of certify, in their default order (--stages picks and orders them):
// "corpus", "families", "scenes", "soups", "extra", "metamorphic", "min-distance", "peers".
// "metamorphic" is no pass of its own: with it, every query of the query stages is also checked
// under the transforms (they go with each query, wherever the word is in the list).
const std::vector<std::string>& certify_stages();

struct CertifyOptions {
  bool quick = false;
  std::string corpus_dir = "corpus";
  std::string out_dir = "certificate";
  // Where the run writes out_dir's files: the private folder of out_dir's OutputFolder, which
  // publishes them whole at the end (fdh/os/output_folder.hpp); empty: out_dir itself.
  std::string write_dir;
  const std::string& files_dir() const { return write_dir.empty() ? out_dir : write_dir; }
  std::uint64_t seed = 1;
  long per_family = -1;  // fuzzed queries per family; -1: 200 quick, 3000 full
  long soups = -1;       // soup pairs for the tree; -1: 30 quick, 300 full
  long peer_cases = -1;  // point sets, and pairs, per peers property; -1: 300 quick, 20000 full
  // The shipped scenes: frames run per scene (-1: 600 quick, the scene's own full) and the
  // stride between certified frames (-1: 50 quick, 10 full).
  long scene_frames = -1;
  int scene_stride = -1;
  std::vector<std::string> extra_files;
  double toi_width = kDefaultToiWidth;  // the enclosure width asked of the times of impact
  // The minimum-separation stage (issue 30): D > 0 asks its contact queries at δ = D; a
  // negative value (the default) at δ = 2^-20 of each query's scale; 0 skips the stage.
  double min_distance = -1;
  // Hears the work as it goes: the stage ("corpus", "generator families", "scenes", ...), how
  // much of it is done and of how much (0: unknown). May be empty.
  ProgressSink progress;
  // Stops the stages at a clean point once spent (between queries and between the transforms
  // of one); what was not reached is listed in Certificate::cut_short.
  Budget budget;
  std::vector<CertifiedPlugin> plugins;  // recorded in the certificate
  // The stages run, in this order (certify_stages()' names); empty: all, in the default order.
  std::vector<std::string> stages;
  bool runs(const std::string& stage) const;
};

// One method's promise on one decision, checked against the exact twin (check/checker.hpp).
struct PromiseCheck {
  std::string method;
  Decision decision = Decision::PointTriangle;
  Promise promise = Promise::Exact;
  long checked = 0, filter_decided = 0, violations = 0;
  long no_answer = 0;  // of the violations: calls past --plugin-timeout (a plug-in's)
};

// One method's time of impact on one TOI decision, under its TimePromise, against the exact
// earliest contact (check/checker.hpp check_time): late, zero, early, enclosure.
struct TimePromiseCheck {
  std::string method;
  Decision decision = Decision::VertexFaceToi;
  TimePromise promise = TimePromise::Enclosure;
  TimeTally tally;  // tally.broken: the violations
  // The first few queries given a time of 0 where t* > 0 ("FILE:LINE" or a generated id).
  std::vector<std::string> zero_queries;
};

// One k-DOP method (one k): its boxes contain the exact FDH; the tree built of its boxes culls
// no exactly overlapping pair.
struct BoxCheck {
  std::string method;
  int k = 0;
  long boxes = 0, box_violations = 0;
  long soup_pairs = 0, exact_pairs = 0, cull_violations = 0;
  bool tree = true;  // fast/'s FDH tree is made of these boxes (not a plug-in's): the soup check
};

// One method of the registry under the metamorphic transforms (check/metamorphic.hpp), on every
// query certify draws: transformed queries checked, and how many changed its verdict. A method
// that promises the exact verdict (robust, the twin) must change none; the others are counted.
// A promised method (not the twin) is also judged on every transformed query against the exact
// verdict of the query, which the transforms keep: each broken promise is a violation.
struct MetamorphicCheck {
  std::string method;
  Promise promise = Promise::None;
  long checked = 0, violations = 0;
  long judged = 0, broken = 0;  // transformed queries judged against the promise; broken
  // Held to invariance: only the exact verdict is invariant. A conservative method (a
  // bounding-volume test) may call a miss a hit in one query and not in its transform.
  bool held() const { return promise == Promise::Exact; }
};

// The minimum-separation stage (issue 30): the promised methods that answer δ > 0
// (Method::answers_min_distance) against the exact δ twin, on the delta- families' queries
// (each at its own δ, its truth known by construction) and on contact queries asked again at
// δ (every 8th query of the corpus and of each family's first cases): verdicts, times and
// the metamorphic transforms (which scale δ with the query).
struct DeltaStage {
  bool run = false;
  double min_distance = -1;  // CertifyOptions::min_distance: < 0 relative to each query
  long family_queries = 0;   // the delta- families' queries checked
  long contact_queries = 0;  // contact queries asked again at δ
  std::vector<std::string> families;
  std::vector<PromiseCheck> promises;
  std::vector<TimePromiseCheck> times;
  long truths = 0, truth_violations = 0;
  std::vector<MetamorphicCheck> metamorphic;
  std::vector<TransformCount> metamorphic_transforms;

  long checks() const;
  long violations() const;
  // "2^-20 of each query's scale" or "1e-06"
  std::string delta_words() const;
};

struct Certificate {
  CertifyOptions options;
  std::string commit, cgal, gmp;
  long corpus_files = 0, corpus_queries = 0, fuzzed_queries = 0, extra_queries = 0;
  std::vector<std::string> families, moving_families;
  // Narrow-phase queries recorded from the shipped scenes (<corpus>/scenes/*.scene).
  long scenes = 0, scene_queries = 0;
  std::vector<PromiseCheck> promises;         // every (method, query decision) with a promise
  std::vector<TimePromiseCheck> times;        // every (method, TOI decision) with a promise
  std::vector<BoxCheck> boxes;                // every k-DOP method
  long truths = 0, truth_violations = 0;      // queries with a stored truth: the twin = the truth
  std::vector<MetamorphicCheck> metamorphic;  // every method of the registry
  // Every transform: the queries it applied to, and those skipped as inexact (it would round,
  // overflow or leave the normal range).
  std::vector<TransformCount> metamorphic_transforms;
  // The own k-DOPs beside the peer libraries' boxes (peers.hpp); shrunk cases in out_dir/peers/,
  // stored ones replayed from corpus_dir/peers/. Only the own rows count as checks here.
  PeersReport peers;
  DeltaStage delta;             // the minimum-separation stage; its checks count in checks() too
  std::string first_violation;  // what went wrong first, and the file it was saved to
  // Every kind of broken promise found (a method, a decision, and a wrong verdict, a wrong or
  // not-a-time time, no answer in --plugin-timeout, ...), in its first case: its words and the
  // file it was saved to. The first is first_violation.
  std::vector<std::string> broken_saved;
  // The stages the budget cut short, in run order: how far each got. Not empty: the checks
  // above cover part of the inputs only, and the certificate certifies nothing.
  std::vector<BudgetCut> cut_short;

  bool complete() const { return cut_short.empty(); }
  bool certified() const { return first_violation.empty() && complete(); }
  const char* mode() const { return options.quick ? "quick" : "full"; }
  // Every check counted above (metamorphic: exact methods' invariance, promised methods'
  // judged transformed queries).
  long checks() const;
  long violations() const;  // every violation counted above (the same)
};

// What certify writes into its folder: the certificate, the first violating case
// (violation-*) and the peers' shrunk cases (peers/): replaced whole by a run
// (fdh/os/output_folder.hpp).
std::vector<std::string> certify_outputs();

// Writes the first violating case (if any) into options.files_dir(). Reads the extra files and
// the scenes before any check, so that bad input is refused before the work starts. Throws
// InputError for bad inputs, std::runtime_error for I/O failures.
Certificate certify(const CertifyOptions& options);

std::string certificate_json(const Certificate& c);

// A cut in words: "corpus: 12 of 2,824 queries", "metamorphic: 1,200 transformed queries
// checked", "peers: not run".
std::string cut_words(const BudgetCut& cut);
std::string certificate_markdown(const Certificate& c);

// certificate.json and certificate.md, each written whole, into c.options.files_dir().
void write_certificate(const Certificate& c);

}  // namespace fdh::verify

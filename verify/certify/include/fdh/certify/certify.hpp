// fdhcert certify: checks the fast library against the exact reference on the corpus, fuzzed
// cases of every family (static and moving), queries recorded from the shipped cloth scenes,
// random triangle soups and any extra query files, and counts each certified property.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/peer_certify/peer_certify.hpp"

namespace fdh::verify {

struct CertifyOptions {
  bool quick = false;
  std::string corpus_dir = "corpus";
  std::string out_dir = "certificate";
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
  // Hears the work as it goes: the stage ("corpus", "generator families", "scenes", ...), how
  // much of it is done and of how much (0: unknown). May be empty.
  ProgressSink progress;
};

// One method's promise on one decision, checked against the exact twin (check/checker.hpp).
struct PromiseCheck {
  std::string method;
  Decision decision = Decision::PointTriangle;
  Promise promise = Promise::Exact;
  long checked = 0, filter_decided = 0, violations = 0;
};

// One method's time of impact on one TOI decision, under its TimePromise, against the exact
// earliest contact (check/checker.hpp check_time): late, zero, early, enclosure.
struct TimePromiseCheck {
  std::string method;
  Decision decision = Decision::VertexFaceToi;
  TimePromise promise = TimePromise::Enclosure;
  TimeTally tally;  // tally.broken: the violations
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
  std::string first_violation;  // what went wrong first, and the file it was saved to

  bool certified() const { return first_violation.empty(); }
  // Every check counted above (metamorphic: exact methods' invariance, promised methods'
  // judged transformed queries).
  long checks() const;
  long violations() const;  // every violation counted above (the same)
};

// Writes the first violating case (if any) into options.out_dir. Throws InputError for bad
// inputs, std::runtime_error for I/O failures.
Certificate certify(const CertifyOptions& options);

std::string certificate_json(const Certificate& c);
std::string certificate_markdown(const Certificate& c);

// certificate.json and certificate.md, each written whole, into c.options.out_dir.
void write_certificate(const Certificate& c);

}  // namespace fdh::verify

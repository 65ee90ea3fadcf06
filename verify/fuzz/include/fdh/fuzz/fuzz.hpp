// fdhcert fuzz: search a generator family (static or moving, vertex-face or edge-edge) for
// queries where a method disagrees with the exact twin of its decision, shrink each to a minimal
// case (fdh/gen/families.hpp: shrunk_failure) of the same class (a false alarm stays a false
// alarm, a miss a miss; the case's kind stays the family's), and store the distinct ones: at
// least one per (method, family, class) found.
//
// Case i of a run is drawn from its own seed (seed, i), so a run is the same whatever the
// number of workers, and a shard is a contiguous range of i. Work goes in chunks; a chunk's
// cases are written (each whole, by rename) before the chunk's done-marker is, so a run killed
// at any moment and restarted loses no case and repeats at most the unfinished chunks.
// Workers are processes, not threads: RapidCheck's generators keep global state.
//
// What a run keeps in OUT/.fuzz/ (a work folder and run folders of fdh/os/work_folder.hpp and
// run_folder.hpp; fdhcert's own folder; nothing else in OUT is touched but the
// case files):
//   lock            held (flock) for the whole run by the run and its workers: a second run on
//                   the same OUT waits briefly for a killed run's workers to die, then refuses.
//   tmp/            every temporary file of every run, and nothing else. A case file or marker
//                   is written there, synced, then renamed into place; a run that goes on (one
//                   that refuses changes nothing) starts by emptying tmp/ (under the lock, so no
//                   live run owns anything in it). A user's files,
//                   whatever their names, are never removed.
//   RUN/manifest    RUN is method.family.seedS.countN.shardIofS (prefixed "metamorphic." or
//                   "toi.wW.tolT." in those modes, and "dD." at --min-distance D > 0, D in
//                   hex-float); the manifest records those parameters and
//                   the mode (with --toi its width and tolerance), and is written before any case.
//   RUN/cases-B-E   done-marker of cases [B, E): `<disagreements> <case file>...`. Markers name
//                   case ranges, not chunk numbers, so a run resumed with any --chunk or
//                   --threads runs exactly the cases no marker covers.
// A run refuses to start while OUT holds an unfinished run with other parameters (mode, method,
// family, seed, count, shard): resuming it with those would not end with its cases.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "fdh/os/budget.hpp"
#include "fdh/os/progress.hpp"

namespace fdh::verify {

// fuzz's bounds: --count N' <= 10^12 and --shard I/N with N <= 10^6, so that N' * N (the
// shard arithmetic of src/fuzz.cpp) stays below 10^18 < 2^63 - 1.
constexpr long kMaxFuzzCount = 1'000'000'000'000L;
constexpr long kMaxFuzzShards = 1'000'000L;
static_assert(kMaxFuzzCount <= INT64_MAX / (kMaxFuzzShards + 1), "count * shard overflows");

struct FuzzOptions {
  std::string method;
  // Look for queries where the method's verdict changes under a transform that keeps the truth
  // (fdh/check/metamorphic.hpp) instead of disagreements with the twin; cases go to
  // OUT/metamorphic/<method>/<family>/. Part of the run's parameters, like the method.
  bool metamorphic = false;
  // Look instead for findings in the method's time of impact (fdh/check/checker.hpp
  // check_time) on a moving family: a missed contact, a late time (t_lo > t*), a time that
  // breaks the method's time promise otherwise, or one earlier than t* by more than
  // toi_tolerance (step units). Each is shrunk keeping its class and stored as
  // OUT/toi/<method>/<family>/<class>-<hash>.vf. The width and tolerance are part of the
  // run's parameters.
  bool toi = false;
  double toi_width = 0x1p-30;     // the enclosure width asked (fdh/ccd/toi.hpp kDefaultToiWidth)
  double toi_tolerance = 0.1;     // fdh/check/checker.hpp kDefaultToiTolerance
  std::string family = "angled";  // any family, static or moving (fdh/gen/families.hpp)
  // The minimum separation δ every case is asked at (Query::min_distance): 0 keeps each case's
  // own (contact, or a delta- family's δ); D > 0 asks every case drawn, and every shrunk one,
  // at δ = D, and the case files say so. Part of the run's parameters when not 0.
  double min_distance = 0;
  std::uint64_t seed = 1;
  long count = 10000;  // cases in the whole run, over all shards
  int shard = 0;       // this process runs shard `shard` of `shards` (0-based)
  int shards = 1;
  int threads = 0;  // worker processes; 0: every core
  int chunk = 500;  // cases per checkpoint step
  std::string out_dir;
  ProgressSink progress;  // hears the cases done and the disagreements found, as it goes
  // How long to wait for OUT's lock before refusing: a killed run's workers die within
  // moments of it, and hold the lock until they have.
  double lock_wait_seconds = 3;
  // Once spent, shrinking stops (the case is stored as far as it shrank) and the workers stop
  // after the case in hand; the cases done are marked, so the same command resumes the rest.
  // Not part of the run's parameters.
  Budget budget;
};

struct FuzzSummary {
  long first = 0, last = 0;        // this shard's cases: [first, last)
  long cases = 0;                  // cases run, including chunks finished by an earlier run
  long resumed = 0;                // of which were done before this run started
  long disagreements = 0;          // raw disagreements before shrinking
  std::set<std::string> distinct;  // file paths of the distinct shrunk cases
  // The raw disagreements by class, which each shrunk case keeps and its file name starts
  // with: "fp" (false alarms) and "fn" (misses); with --toi "missed", "late", "broken",
  // "early"; with --metamorphic "metamorphic". Cases of a run resumed from before classes were
  // named count as "disagrees".
  std::map<std::string, long> by_class;
  // The budget ran out: cases [first, last) were not all run (`cases` counts those that were),
  // and `shrink_cut` cases were stored less shrunk than they could have been.
  bool cut = false;
  long shrink_cut = 0;
};

// The run cannot start on this OUT: another run holds it, or OUT holds an unfinished run with
// other parameters. The message says which and what to do (fdhcert: exit status 2).
struct FuzzRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws std::invalid_argument for an unknown method or family or an impossible count or
// shard, FuzzRefused as above, std::runtime_error for I/O failures (naming the path).
FuzzSummary run_fuzz(const FuzzOptions& opt);

// The first case of shard `shard` (0-based) of `shards` over `count` cases: count·shard/shards,
// without overflow for any count >= 0 and 0 <= shard <= shards.
long shard_begin(long count, int shard, int shards);

}  // namespace fdh::verify

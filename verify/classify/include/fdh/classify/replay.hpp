// The replay job (fdhcert replay): stored cases re-run; the exact twin must still give each
// stored truth, and every other method's disagreements are listed in the checker's words
// (check/findings.hpp), with --toi its times too, all asked at one minimum separation δ.
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/findings.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

struct ReplayOptions {
  std::vector<std::string> paths;    // case files, or folders of them (every *.vf below)
  std::vector<std::string> methods;  // empty: every method
  bool toi = false;
  double width = kDefaultToiWidth;
  double tolerance = kDefaultToiTolerance;  // how early a time may be before it is listed
  // δ: every case is asked at this minimum separation; a case's stored truth counts only where
  // its own δ is this one (elsewhere it is the twin's). 0: contact, today's question.
  double min_distance = 0;

  // Throws std::invalid_argument naming the first bad option: no path, an unknown method, a
  // width outside [2^-52, 1], a tolerance outside [0, 1], δ negative or not finite.
  void validate() const;
};

// One method's cases against the stored truths, and each disagreement with the twin in the
// checker's words, counted by direction and by what the method's promise makes of it.
struct Failing {
  std::string name;
  Promise promise = Promise::None;
  std::vector<std::string> cases;                 // where it differs from the stored truth
  std::vector<std::string> words;                 // per case: the checker's words, or why none
  std::vector<std::string> misses, false_alarms;  // against the twin
  DisagreementTally tally;
};

// One method's times: the cases where it is late, 0 too early, earlier than the tolerance or
// breaks its promise, and of those the ones its time promise allows.
struct ReplayTimes {
  std::string method;
  TimePromise promise = TimePromise::None;
  std::vector<std::string> late, zero, early, broken, allowed;
  std::vector<std::string> words;  // per listed case: WHERE: the checker's judged words
};

struct ReplayResult {
  ReplayOptions options;
  std::size_t cases = 0;
  std::vector<std::string> twin_mismatches;  // where the twin lost its stored truth
  std::vector<Failing> failing;              // per method, in the order run
  std::vector<ReplayTimes> times;            // with --toi: per method that gives a time

  // `fdhcert replay --json`'s object.
  nlohmann::ordered_json to_json() const;
  // `fdhcert replay`'s report, as printed.
  std::string text() const;
  // replay.json and replay.txt into `dir` (made if missing), each whole.
  void write(const std::string& dir) const;
};

// The stored cases read (InputError for bad input, a case without a truth, no case at all),
// re-run and judged. Validates the options first.
ReplayResult replay_job(const ReplayOptions& options);

}  // namespace fdh::verify

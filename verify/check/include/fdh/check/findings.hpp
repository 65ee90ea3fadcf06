// What the checker finds in a batch: every query × method judged against the exact twin, and the
// twin against a file's truth, as one list in the checker's words. classify, replay and certify
// print findings; this is the one loop "query × method → judge → words".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

// How a finding names its query: "FILE:LINE" (replay) or "FILE:LINE (query ID)" (classify).
enum class Place { Line, LineAndId };
std::string place_of(const QueryRecord& r, Place place);

// One disagreement. For a method: its verdict against the twin's, judged by its promise. For
// the twin itself (method = the twin's name, truth = true): the twin's verdict against the
// file's truth, always Broken.
struct Finding {
  std::size_t query = 0;  // index into the records
  std::string method;
  bool truth = false;  // the twin against the file's truth (not a method against the twin)
  bool said = false;   // the verdict found wanting
  Judgement judgement = Judgement::Kept;
  std::string words;  // the checker's words (verdict_words), with the place
};

// The twin against each file's truth first, in query order; then each method of c (in order,
// the twin left out) against the twin, query by query. `records` are c's queries in order.
std::vector<Finding> findings(const Classification& c, const std::vector<QueryRecord>& records,
                              const std::vector<Method>& methods, Place place = Place::LineAndId);

// The time-of-impact twin: one method's time on one query that is late, 0 too early, earlier
// than `tolerance` steps, or breaks the method's time promise (checker.hpp TimeCheck).
struct TimeFinding {
  std::size_t query = 0;
  std::string method;
  TimePromise promise = TimePromise::None;
  TimeCheck check;
  bool early = false;  // check.early > tolerance
  Judgement judgement = Judgement::Kept;
  std::string words;  // judged_time_words, without the place
};

// Every method of toi, in order, query by query. `methods` must hold toi's methods by name.
std::vector<TimeFinding> time_findings(const ToiClassification& toi,
                                       const std::vector<Method>& methods,
                                       double tolerance = kDefaultToiTolerance);

}  // namespace fdh::verify

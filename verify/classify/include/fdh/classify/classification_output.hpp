// Prints a Classification: a table for people, JSON for programs, CSV per query.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/check/query_times.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

struct ReportContext {
  int gate_k = 0;           // the --gate in force, 0 if none
  double min_distance = 0;  // the δ every query was asked at (0: contact, not mentioned)
};

// One classification per file, in the order read, and their total.
struct FileClassification {
  std::string file;
  Classification c;
};

// One block per file when there are several, then the total. A method that applies to none of
// a block's queries shows "n/a". A δ > 0 is named in each block's title line.
void print_table(std::ostream& os, const std::vector<FileClassification>& files,
                 const Classification& total, const ReportContext& ctx);

// {"queries": N, "static_vf": S, "moving_vf": M, "edge_edge": E,
//  "truth": "file"|"exact"|"mixed",
//  "methods": {"<name>": {"tp":…, "tn":…, "fp":…, "fn":…, "na":…, "ns_per_query":…}, …},
//  "gate": K, "files": [{"file": "…", "queries": …, …, "methods": {…}}, …]}
// for the total, then each file. Counts and time are null where a method applies to nothing.
nlohmann::ordered_json classification_json(const std::vector<FileClassification>& files,
                                           const Classification& total, const ReportContext& ctx);

// classify --time: each method's thread CPU time per query, each query timed alone
// (check/query_times.hpp, the least disturbed of `rounds` batches), as a table
//   thread CPU time per query (...):
//     method   queries   median ns   p90 ns   max ns   slowest
// and as {"rounds": R, "methods": {"<name>": {"queries": N, "median_ns": …, "p90_ns": …,
// "max_ns": …, "slowest": "FILE:LINE (query ID)"}, …}} (times and slowest null where the method
// applies to nothing). `queries` are the records the spreads' indices refer to.
void print_cpu_times(std::ostream& os, const std::vector<TimeSpread>& spreads,
                     const std::vector<QueryRecord>& queries, int rounds);
nlohmann::ordered_json cpu_times_json(const std::vector<TimeSpread>& spreads,
                                      const std::vector<QueryRecord>& queries, int rounds);

// id,truth,<method>,…,contact,time with one row per query; verdicts are 0, 1 or n/a. Contact
// and time come from the exact test of the query's own decision: for a static vertex-face
// query the contact kind (face, edge, vertex, in-plane, none) and the rational time of exact
// point–triangle; for a moving one (vertex-face or edge-edge) "moving" and the earliest time of
// exact CCD, a rational or "lo..hi" around an irrational one. No contact: "none" and "".
// With queries from several files the id is "<file>:<id>".
// With `toi` (classify --toi), each row also has the TOI columns of toi_report.hpp after time.
std::string per_query_csv(const std::vector<QueryRecord>& queries, const Classification& c,
                          const ToiClassification* toi = nullptr);

}  // namespace fdh::verify

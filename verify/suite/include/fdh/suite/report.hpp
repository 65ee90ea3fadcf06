// Prints a Classification: a table for people, JSON for programs, CSV per query.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "fdh/query.hpp"
#include "fdh/check/classify.hpp"

namespace fdh::verify {

struct ReportContext {
  int gate_k = 0;  // the --gate in force, 0 if none
};

// One classification per file, in the order read, and their total.
struct FileClassification {
  std::string file;
  Classification c;
};

// One block per file when there are several, then the total. A method that applies to none of
// a block's queries shows "n/a".
void print_table(std::ostream& os, const std::vector<FileClassification>& files,
                 const Classification& total, const ReportContext& ctx);

// {"queries": N, "static_vf": S, "moving_vf": M, "edge_edge": E,
//  "truth": "file"|"exact"|"mixed", "gate": K,
//  "methods": {"<name>": {"tp":…, "tn":…, "fp":…, "fn":…, "na":…, "ns_per_query":…}, …},
//  "files": [{"file": "…", "queries": …, …, "methods": {…}}, …]}
// for the total, then each file. Counts and time are null where a method applies to nothing.
void print_json(std::ostream& os, const std::vector<FileClassification>& files,
                const Classification& total, const ReportContext& ctx);

// id,truth,<method>,…,contact,time with one row per query; verdicts are 0, 1 or n/a; contact and
// time are exact's contact kind ("moving" for a moving query) and earliest contact time (a
// rational, or "lo..hi" around an irrational one; empty for no contact).
// With queries from several files the id is "<file>:<id>".
std::string per_query_csv(const std::vector<Query>& queries, const Classification& c);

}  // namespace fdh::verify

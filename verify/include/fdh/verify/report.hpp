// Prints a Classification: a table for people, JSON for programs, CSV per query.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "fdh/query.hpp"
#include "fdh/verify/classify.hpp"

namespace fdh::verify {

struct ReportContext {
  int gate_k = 0;           // the --gate in force, 0 if none
  std::size_t skipped = 0;  // queries left out (moving triangles, edge-edge)
};

void print_table(std::ostream& os, const Classification& c, const ReportContext& ctx);

// {"queries": N, "truth": "file"|"exact"|"mixed", "gate": K, "skipped": S,
//  "methods": {"<name>": {"tp":…, "tn":…, "fp":…, "fn":…, "ns_per_query":…}, …}}
void print_json(std::ostream& os, const Classification& c, const ReportContext& ctx);

// id,truth,<method>,…,contact,time with one row per query; verdicts are 0 or 1; contact and
// time are exact's contact kind and earliest contact time (a rational, empty for no contact).
// With queries from several files the id is "<file>:<id>".
std::string per_query_csv(const std::vector<Query>& queries, const Classification& c);

}  // namespace fdh::verify

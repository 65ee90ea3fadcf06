// The classify job (fdhcert classify, fdhcert.classify): every method side by side on query
// files, counted against each file's truth or the exact twin; optionally the times of impact
// (--toi), each query timed alone (--time, --time-ratio), all asked at one minimum separation δ
// (--min-distance). The CLI and Python only word the options and print or convert the Result.
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "fdh/check/findings.hpp"
#include "fdh/check/query_times.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/classify/classify_files.hpp"

namespace fdh::verify {

struct ClassifyOptions {
  std::vector<std::string> files;
  std::vector<std::string> methods;  // empty: every method
  int gate = 0;                      // 0, or the k of the k-DOP gate on the paper's methods
  // The kind of CSV files whose path names no vertex-face or edge-edge folder: "vertex-face",
  // "edge-edge" or "" (from the path).
  std::string kind;
  bool toi = false;  // also the times of impact
  double width = kDefaultToiWidth;
  bool time = false;       // also each query timed alone: median, p90, maximum per method
  std::string time_ratio;  // a base method: per-query time ratios to it
  double ratio_limit = 1.1;
  int rounds = 7;
  // δ: every query is asked at this minimum separation; a file's truth counts only for a query
  // whose own δ (Query::min_distance) is this one. 0: contact, today's question.
  double min_distance = 0;
  // Hears each method's pass over the queries (check/classify.hpp); may be empty.
  ProgressSink progress;

  // Throws std::invalid_argument naming the first bad option (the CLI's usage error, Python's
  // ValueError): no file, an unknown method, kind or gate, a width outside [2^-52, 1], rounds
  // outside 1..100, a ratio limit outside [1e-3, 1e3], δ negative or not finite.
  void validate() const;
};

// Every query timed alone (check/query_times.hpp), for --time and --time-ratio.
struct QueryTimings {
  std::vector<Method> methods;          // the selected ones, then --time-ratio's base if not
  std::vector<std::vector<double>> ns;  // ns[m][i]
  std::vector<TimeSpread> spreads;      // --time: the selected methods' spreads
  std::vector<TimeRatio> ratios;        // --time-ratio: each method over the base
  std::vector<double> mean_ns;          // --time-ratio: per method of `methods`
};

struct ClassifyResult {
  ClassifyOptions options;
  std::vector<Method> methods;
  ClassifiedFiles classified;
  std::optional<ToiClassifiedFiles> toi;
  std::optional<QueryTimings> timings;
  std::vector<Finding> findings;           // check/findings.hpp, classify's places
  std::vector<TimeFinding> time_findings;  // with --toi

  // How many truths and promises broke (classify --check exits 1 when not 0): the twin against
  // a file's truth, each promised method's broken verdicts and broken times.
  std::size_t broken() const;
  // `fdhcert classify --json`'s object.
  nlohmann::ordered_json to_json() const;
  // `fdhcert classify`'s tables, as printed.
  std::string text() const;
  // The lines classify prints on standard error: each finding of a promised method (broken, and
  // the first 10 allowed per method, the rest counted) and each broken time (the first 16 per
  // method), each line starting "fdhcert: ".
  std::string findings_text() const;
  // --per-query's CSV (classification_output.hpp per_query_csv).
  std::string per_query_csv() const;
  // classify.json, classify.txt and per-query.csv into `dir` (made if missing), each whole.
  void write(const std::string& dir) const;
};

// The files read (InputError for bad input), every query asked at options.min_distance,
// classified, and the rest the options ask for. Validates the options first.
ClassifyResult classify_job(const ClassifyOptions& options);

}  // namespace fdh::verify

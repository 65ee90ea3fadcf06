// Query files classified as `fdhcert classify` does it, for the program and the Python module
// alike: every file read (native or benchmark CSV), the files without queries left out, every
// query asked at one minimum separation δ, each file classified (check/classify.hpp) and the
// total joined.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/classify/classification_output.hpp"
#include "fdh/io/query_record.hpp"

namespace fdh::verify {

struct ClassifiedFiles {
  std::vector<FileClassification> files;  // in the order given, those without queries left out
  Classification total;
  std::vector<QueryRecord> all;  // every query read, in order, as asked (at δ)
};

// Every record asked at δ (Query::min_distance = δ): a file's truth answers the question at the
// record's own δ, so it is kept only where that δ is this one, and dropped (Unknown) elsewhere.
// δ = 0 on records at 0 changes nothing.
void ask_at(std::vector<QueryRecord>& records, double min_distance);

// kind: the kind of CSV files whose path names no vertex-face or edge-edge folder, or nullopt
// (from the path). Every query is asked at min_distance (ask_at). Throws InputError for bad
// input, and when no file holds a query.
ClassifiedFiles classify_files(const std::vector<std::string>& files,
                               const std::vector<Method>& methods, std::optional<QueryKind> kind,
                               double min_distance = 0, const ProgressSink& progress = {});

// The times of impact of the same files (`classify --toi`): per file, in the order of
// `classified.files`, and in total.
struct ToiClassifiedFiles {
  std::vector<std::pair<std::string, ToiClassification>> files;
  ToiClassification total;
};
ToiClassifiedFiles classify_toi_files(const ClassifiedFiles& classified,
                                      const std::vector<Method>& methods, double width,
                                      const ProgressSink& progress = {});

}  // namespace fdh::verify

// Query files classified as `fdhcert classify` does it, for the program and the Python module
// alike: every file read (native or benchmark CSV), the files without queries left out, each
// file classified (check/classify.hpp) and the total joined.
#pragma once

#include <string>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/check/classify_toi.hpp"
#include "fdh/io/query_record.hpp"
#include "fdh/run/classification_output.hpp"

namespace fdh::verify {

struct ClassifiedFiles {
  std::vector<FileClassification> files;  // in the order given, those without queries left out
  Classification total;
  std::vector<QueryRecord> all;  // every query read, in order
};

// kind: "vf" or "ee" for CSV files whose path names no vertex-face or edge-edge folder, or ""
// (from the path). Throws InputError for bad input, and when no file holds a query.
ClassifiedFiles classify_files(const std::vector<std::string>& files,
                               const std::vector<Method>& methods, const std::string& kind);

// The times of impact of the same files (`classify --toi`): per file, in the order of
// `classified.files`, and in total.
struct ToiClassifiedFiles {
  std::vector<std::pair<std::string, ToiClassification>> files;
  ToiClassification total;
};
ToiClassifiedFiles classify_toi_files(const ClassifiedFiles& classified,
                                      const std::vector<Method>& methods, double width);

}  // namespace fdh::verify

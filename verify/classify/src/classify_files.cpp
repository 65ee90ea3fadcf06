#include "fdh/classify/classify_files.hpp"

#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/record_scope.hpp"

namespace fdh::verify {

void ask_at(std::vector<QueryRecord>& records, double min_distance) {
  for (QueryRecord& r : records) {
    if (r.query.min_distance != min_distance) r.truth = Truth::Unknown;
    r.query.min_distance = min_distance;
  }
}

ClassifiedFiles classify_files(const std::vector<std::string>& files,
                               const std::vector<Method>& methods, std::optional<QueryKind> kind,
                               double min_distance, const ProgressSink& progress) {
  std::vector<std::pair<std::string, std::vector<QueryRecord>>> read;  // every file read first
  for (const std::string& f : files) {
    std::vector<QueryRecord> qs = read_query_file(f, kind);
    ask_at(qs, min_distance);
    if (!qs.empty()) read.emplace_back(f, std::move(qs));
  }
  if (read.empty()) throw InputError(files.empty() ? "" : files.front(), 0, "no query to classify");
  ClassifiedFiles out;
  std::vector<Classification> parts;
  for (auto& [file, qs] : read) {
    const std::vector<Query> queries = queries_of(qs);
    const RecordScope asking(qs, queries);  // a plug-in's crash names FILE:LINE
    parts.push_back(classify(queries, truths_of(qs), methods, progress));
    out.files.push_back({file, parts.back()});
    out.all.insert(out.all.end(), qs.begin(), qs.end());
  }
  out.total = join(parts);
  return out;
}

ToiClassifiedFiles classify_toi_files(const ClassifiedFiles& classified,
                                      const std::vector<Method>& methods, double width,
                                      const ProgressSink& progress) {
  ToiClassifiedFiles out;
  std::vector<ToiClassification> parts;
  std::size_t begin = 0;
  for (const FileClassification& f : classified.files) {
    const auto first = classified.all.begin() + std::ptrdiff_t(begin);
    const std::vector<QueryRecord> records(first, first + std::ptrdiff_t(f.c.queries));
    const std::vector<Query> qs = queries_of(records);
    begin += f.c.queries;
    const RecordScope asking(records, qs);  // a plug-in's hang or crash names FILE:LINE
    parts.push_back(classify_toi(qs, methods, width, progress));
    out.files.emplace_back(f.file, parts.back());
  }
  out.total = join(parts);
  return out;
}

}  // namespace fdh::verify

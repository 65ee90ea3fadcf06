#include "fdh/audit_job/audit_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "fdh/audit_job/audit_job.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/folders.hpp"
#include "fdh/os/output_folder.hpp"

namespace fdh::verify {
namespace {

std::string file_text(const std::string& path, const std::string& missing) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, missing);
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "cannot be read");
  return s.str();
}

struct ReadPart {
  std::string dir, file;
  AuditReport report;
};

ReadPart read_part(const std::string& dir) {
  const std::string file = (std::filesystem::path(dir) / "audit.json").string();
  const std::string text =
      file_text(file, "no such file (`fdhcert audit ... --part I/N --out DIR` writes it)");
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(file, 0, "not a JSON object");
  AuditReport r = AuditReport::from_json(j, file);
  if (!r.part()) throw InputError(file, 0, "not a part's certificate (no \"part\": audit --part)");
  return {dir, file, std::move(r)};
}

}  // namespace

MergedAudit merge_audit_parts(const std::vector<std::string>& dirs) {
  if (dirs.empty()) throw std::invalid_argument("--merge needs the parts' folders");
  std::vector<ReadPart> read;
  for (const std::string& d : dirs) read.push_back(read_part(d));
  // In the parts' order (given order on ties); indices sorted, so no ReadPart is moved twice.
  std::vector<std::size_t> order(read.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return read[a].report.part()->index < read[b].report.part()->index;
  });
  std::vector<ReadPart> parts;
  for (const std::size_t i : order) parts.push_back(std::move(read[i]));
  const AuditPart& first = *parts.front().report.part();
  if (first.index != 1)
    throw InputError(
        parts.front().file, 0,
        fmt::format("part {}/{}, and no part 1/{} is given", first.index, first.of, first.of));
  MergedAudit m;
  m.report_.emplace(parts.front().report);
  for (const KeptViolation& k : m.report_->kept())
    if (!k.case_file.empty())
      m.copies_.emplace_back(parts.front().dir + "/" + k.case_file, k.case_file);
  int pictured = m.report_->clean() ? -1 : 0;  // the part whose picture is the run's
  for (std::size_t i = 1; i < parts.size(); ++i) {
    std::vector<std::pair<std::string, std::string>> renamed;
    try {
      renamed = m.report_->append(parts[i].report);
    } catch (const std::invalid_argument& e) {
      throw InputError(parts[i].file, 0, e.what());
    }
    for (const auto& [from, to] : renamed) m.copies_.emplace_back(parts[i].dir + "/" + from, to);
    if (pictured < 0 && !m.report_->clean()) pictured = int(i);
  }
  try {
    m.report_->end_parts();
  } catch (const std::invalid_argument& e) {
    throw InputError(parts.back().file, 0, e.what());
  }
  if (pictured >= 0)
    m.copies_.emplace_back(parts[std::size_t(pictured)].dir + "/first-violation.png",
                           "first-violation.png");
  return m;
}

nlohmann::ordered_json MergedAudit::to_json() const {
  return report_->json();
}

std::string MergedAudit::text() const {
  return report_->text();
}

void MergedAudit::write(const std::string& dir) const {
  OutputFolder out(dir, audit_outputs());  // published whole, as a run's (issue 34)
  out.publish([&](const std::string& into) {
    // The parts' files first: a part without them stops the merge before its certificate.
    for (const auto& [from, to] : copies_) {
      make_folder((std::filesystem::path(into) / to).parent_path().string());
      write_file_atomically(into + "/" + to,
                            file_text(from, "no such file: the part is incomplete"));
    }
    write_file_atomically(into + "/audit.json", json_text(report_->json(), "audit.json"));
    write_file_atomically(into + "/audit.md", report_->markdown());
  });
}

}  // namespace fdh::verify

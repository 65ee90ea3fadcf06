// The merge of `fdhcert audit --part I/N --out DIR` runs (`fdhcert audit --merge DIR... --out
// DIR`): the parts' certificates (each DIR/audit.json, with its "part" block) joined in order into
// the certificate the whole run gives, the same JSON apart from the costs, with the first
// violation's picture and the case files copied from the parts that hold them (docs/cluster.md).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fdh/audit_job/audit_report.hpp"

namespace fdh::verify {

class MergedAudit {
 public:
  const AuditReport& report() const { return *report_; }
  nlohmann::ordered_json to_json() const;
  std::string text() const;
  int exit_status() const { return report_->exit_status(); }
  // DIR/audit.json, DIR/audit.md, DIR/first-violation.png and DIR/cases/*.vf, each whole.
  void write(const std::string& dir) const;

 private:
  friend MergedAudit merge_audit_parts(const std::vector<std::string>& dirs);
  std::optional<AuditReport> report_;
  std::vector<std::pair<std::string, std::string>> copies_;  // (a part's file, name under DIR)
};

// The parts in the folders given, in any order: every part 1/N to N/N of one sequence exactly
// once. Throws InputError naming a part's audit.json that is missing, not a part's certificate,
// or not of the same run as the others.
MergedAudit merge_audit_parts(const std::vector<std::string>& dirs);

}  // namespace fdh::verify

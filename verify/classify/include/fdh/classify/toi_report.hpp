// Prints a ToiClassification (`classify --toi`): a table for people, JSON for programs, and the
// per-query enclosures as CSV columns.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "fdh/check/classify_toi.hpp"

namespace fdh::verify {

using FileToi = std::pair<std::string, ToiClassification>;

// One block per file when there are several, then the total: per method its time promise, the
// late TOIs (a contact missed or t_lo > t*), TOIs of 0 where t* > 0, verdict errors, enclosures
// that miss t* or are wider than asked, how early (t* - t_lo, step units: maximum and median)
// and ns per query.
void print_toi_table(std::ostream& os, const std::vector<FileToi>& files,
                     const ToiClassification& total);

// {"width": W, "methods": {"<name>": {"promise": P, "checked": N, "contacts": C, "late": L,
//  "zero": Z, "verdict_errors": V, "not_enclosed": E, "too_wide": X, "broken": B,
//  "early_max": M, "early_median": D, "toi_ns_per_query": T, "na": A}, ...},
//  "files": [{"file": F, "methods": {...}}, ...]}
nlohmann::ordered_json toi_json(const std::vector<FileToi>& files, const ToiClassification& total);

// Appends a time tally's counts to j, in the order every writer of them uses (classify's "toi"
// block, the certificate's "times"): checked, contacts, late, zero, verdict_errors, not_enclosed,
// too_wide.
void add_time_counts(nlohmann::ordered_json& j, const TimeTally& t);

// The per-query CSV's TOI columns: the header ",<m> t_lo,<m> t_hi" per method, and row i's
// fields: each time in the fewest digits that read back exactly, "" and "" where the method
// finds no contact, n/a where it gives no time.
std::string toi_csv_header(const ToiClassification& c);
std::string toi_csv_fields(const ToiClassification& c, std::size_t i);

}  // namespace fdh::verify

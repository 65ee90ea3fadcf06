// What checking some queries, soups or boxes adds to the certificate, merged in input order:
// the certifier's tally (certifier.hpp). Private to fdh_certify.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fdh/certify/certify.hpp"

namespace fdh::verify {

// The zero times named per method and decision (TimePromiseCheck::zero_queries).
inline constexpr std::size_t kZeroNamed = 3;

// What checking some queries (or soups) adds to the certificate: counts in the certificate's
// rows, and the first violation of each kind. Parts of a run are merged in the order of their
// inputs, so the certificate does not depend on how the run was cut (parallel.hpp).
struct CertifyTally {
  std::vector<PromiseCheck> promises;
  std::vector<TimePromiseCheck> times;
  std::vector<BoxCheck> boxes;
  std::vector<MetamorphicCheck> metamorphic;
  std::vector<TransformCount> transforms;  // the metamorphic transforms applied and skipped
  long truths = 0, truth_violations = 0;
  long queries = 0;  // the queries checked (certify counts them per source)
  long skipped = 0;  // the queries not checked: the budget was spent (fdh/os/budget.hpp)
  // The first violation of each kind (`key`: method, decision and what broke), its words and
  // the case file that shows it (a name in out_dir and the file's text): every broken promise
  // is named and saved once, the certificate's first also as first_violation.
  struct Found {
    std::string key, what, file, text;
  };
  std::vector<Found> found;

  bool has(const std::string& key) const {
    return std::any_of(found.begin(), found.end(), [&](const Found& f) { return f.key == key; });
  }
  void keep(const Found& f) {
    if (!has(f.key)) found.push_back(f);
  }

  void add(const CertifyTally& later) {
    for (std::size_t i = 0; i < promises.size(); ++i) {
      promises[i].checked += later.promises[i].checked;
      promises[i].filter_decided += later.promises[i].filter_decided;
      promises[i].violations += later.promises[i].violations;
      promises[i].no_answer += later.promises[i].no_answer;
    }
    for (std::size_t i = 0; i < times.size(); ++i) {
      times[i].tally.merge(later.times[i].tally, 0);
      for (const std::string& z : later.times[i].zero_queries)
        if (times[i].zero_queries.size() < kZeroNamed) times[i].zero_queries.push_back(z);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const BoxCheck& b = later.boxes[i];
      boxes[i].boxes += b.boxes, boxes[i].box_violations += b.box_violations;
      boxes[i].soup_pairs += b.soup_pairs, boxes[i].exact_pairs += b.exact_pairs;
      boxes[i].cull_violations += b.cull_violations;
    }
    for (std::size_t i = 0; i < metamorphic.size(); ++i) {
      metamorphic[i].checked += later.metamorphic[i].checked;
      metamorphic[i].violations += later.metamorphic[i].violations;
      metamorphic[i].judged += later.metamorphic[i].judged;
      metamorphic[i].broken += later.metamorphic[i].broken;
    }
    for (std::size_t i = 0; i < transforms.size(); ++i) {
      transforms[i].applied += later.transforms[i].applied;
      transforms[i].skipped += later.transforms[i].skipped;
    }
    truths += later.truths, truth_violations += later.truth_violations;
    queries += later.queries, skipped += later.skipped;
    for (const Found& f : later.found) keep(f);
  }
};

}  // namespace fdh::verify

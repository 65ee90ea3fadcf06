// The minimum-separation stage's own words and tallies (certify.hpp's DeltaStage), which the
// certificate's totals add in.
#include <fmt/format.h>

#include "fdh/certify/certify.hpp"

namespace fdh::verify {

std::string DeltaStage::delta_words() const {
  if (min_distance < 0) return "2^-20 of each query's scale";
  return fmt::format("{}", min_distance);  // the shortest text that reads back as D
}

long DeltaStage::checks() const {
  long n = truths;
  for (const PromiseCheck& p : promises) n += p.checked;
  for (const TimePromiseCheck& p : times) n += p.tally.checked;
  for (const MetamorphicCheck& m : metamorphic) n += (m.held() ? m.checked : 0) + m.judged;
  return n;
}

long DeltaStage::violations() const {
  long n = truth_violations;
  for (const PromiseCheck& p : promises) n += p.violations;
  for (const TimePromiseCheck& p : times) n += p.tally.broken;
  for (const MetamorphicCheck& m : metamorphic) n += (m.held() ? m.violations : 0) + m.broken;
  return n;
}

}  // namespace fdh::verify

// What fdhcert fuzz looks for in a case, and the case file it stores for one. Private to
// fdh_fuzz (fuzz.cpp).
#pragma once

#include <string>

#include "fdh/check/registry.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

struct FuzzTarget {
  Method method;
  // Look for metamorphic failures (check/metamorphic.hpp) instead of disagreements.
  bool metamorphic = false;

  // The method applies to q and disagrees with the exact twin there (the checker); or, with
  // `metamorphic`, its verdict changes under a transform of q.
  bool fails(const Query& q) const;

  // The folder of the cases under OUT: <method>/<family>, or metamorphic/<method>/<family>.
  std::string case_folder(const std::string& family) const;

  // The case file of a failing query shrunk from `family`: the twin's verdict as its truth, and
  // comments saying what the method and the twin answer, with the exact contact (kind and time
  // for a static query, the earliest CCD contact time for a moving one); a metamorphic case also
  // names the transform and the method's verdicts before and after it. It depends on the query
  // alone, so that any number of workers and shards write identical files.
  std::string case_text(const Query& q, const std::string& family) const;
};

}  // namespace fdh::verify

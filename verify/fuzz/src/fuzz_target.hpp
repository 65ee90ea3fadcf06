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
  // Look for findings in the method's time of impact (check_time) instead of disagreements,
  // asking for enclosures `width` wide; an early time is a finding when t* - t_lo exceeds
  // `tolerance` (step units).
  bool toi = false;
  double width = kDefaultToiWidth, tolerance = 0;

  // The class of what the method gets wrong on q, "" for nothing: the direction of a
  // disagreement with the exact twin, "fp" (a false alarm) or "fn" (a miss), where the method
  // applies to q; with `metamorphic`, "broken-promise" (its answer on a transform of q breaks its
  // promise against the twin's verdict on q) or "metamorphic" (its verdict changes under a
  // transform of q); or with `toi` one of "missed" (a contact missed), "late" (t_lo after t*),
  // "broken" (the time breaks the method's promise otherwise) and "early" (t_lo before t* by more
  // than `tolerance`). Shrinking keeps the class of the case drawn: a false alarm shrinks to a
  // false alarm.
  std::string finding(const Query& q) const;

  // The folder of the cases under OUT: <method>/<family>, metamorphic/<method>/<family> or
  // toi/<method>/<family>.
  std::string case_folder(const std::string& family) const;
  // A case's file name: <class>-<hash>.vf (fp-, fn-, or a TOI class), or <hash>.vf with
  // `metamorphic`.
  std::string case_name(const Query& q) const;

  // The case file of a failing query shrunk from `family`: the twin's verdict as its truth, and
  // comments saying what the method and the twin answer, with the exact contact (kind and time
  // for a static query, the earliest CCD contact time for a moving one); a metamorphic case also
  // names the transform and the method's verdicts before and after it, a TOI case the method's
  // enclosure and what the checker found in it; a disagreement's case names its direction in
  // its first comment and its id (M/F/fp, M/F/fn). It depends on the query alone, so that any
  // number of workers and shards write identical files.
  std::string case_text(const Query& q, const std::string& family) const;
};

// The class a stored case's path names (case_name): "fp" for .../fp-<hash>.vf; for a name with
// no class (<hash>.vf: a metamorphic case, or a disagreement stored before classes were named)
// "metamorphic" or "disagrees" after `metamorphic`.
std::string class_of_case_file(const std::string& path, bool metamorphic);

}  // namespace fdh::verify

// What fuzz looks for, and the case files it writes (fuzz_target.hpp).
#include "fuzz_target.hpp"

#include <cstdio>

#include "fdh/check/checker.hpp"
#include "fdh/check/contact.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/record_scope.hpp"

namespace fdh::verify {
namespace {

// The class of a time check's finding (fuzz_target.hpp), "" for none. A missed contact and a
// late time are both late under every promise (checker.hpp), but apart: one is a verdict error,
// the other a time after t*, and a shrunk case keeps which.
std::string time_finding(const TimeCheck& c, double tolerance) {
  if (c.garbage) return "broken";
  if (c.late) return c.said.hit ? "late" : "missed";
  if (!c.kept) return "broken";
  if (c.early > tolerance) return "early";
  return "";
}

// The direction of a disagreement: "fp" (a false alarm: hit where the twin says no) or "fn" (a
// miss: no where the twin says hit), "" where the two agree.
std::string direction(const Verdicts& v) {
  if (v.agree()) return "";
  return v.said ? "fp" : "fn";
}

// The direction in words, for the case file's comment.
std::string direction_words(const std::string& d) {
  return d == "fp" ? "a false alarm (FP)" : "a miss (FN)";
}

// A metamorphic case: the transform, and the method's verdicts or the promise it broke there.
std::string metamorphic_case_text(const Method& m, const QueryRecord& r, const TwinContact& contact,
                                  const std::string& family) {
  const MetamorphicFailure f = *metamorphic_finding_failure(m, r.query);
  const std::string broken = f.kept ? "" : " (breaks " + std::string(to_string(m.promise)) + ")";
  return case_file_text(r,
                        {describe(m, f) + broken + "; exact says " + contact_words(contact) + ".",
                         "Shrunk by fdhcert fuzz --metamorphic from family " + family + "."});
}

}  // namespace

std::string FuzzTarget::finding(const Query& q) const {
  if (metamorphic) return metamorphic_finding(method, q);
  if (toi) return method.gives_toi(q) ? time_finding(check_time(method, q, width), tolerance) : "";
  return method.applies_to(q) ? direction(check(method, q)) : "";
}

std::string FuzzTarget::case_folder(const std::string& family) const {
  return (metamorphic ? "metamorphic/" : toi ? "toi/" : "") + method.name + "/" + family;
}

std::string FuzzTarget::case_name(const Query& q) const {
  return (metamorphic ? "" : finding(q) + "-") + case_hash(q) + ".vf";
}

// The exact contact, computed once, gives the twin's verdict (the case's truth) and its words.
std::string FuzzTarget::case_text(const Query& q, const std::string& family) const {
  const TwinContact contact = twin_contact(q);
  const QueryRecord r{q, case_folder(family), truth_of(contact.hit), "", 0};
  const RecordScope asking(r);
  if (metamorphic) return metamorphic_case_text(method, r, contact, family);
  if (toi) {
    const TimeCheck c = check_time(method, q, width);
    const std::string cls = time_finding(c, tolerance);
    char early[64] = "";
    if (cls == "early") std::snprintf(early, sizeof early, " (early by %.3g of the step)", c.early);
    return case_file_text(r, {"TOI " + cls + early + ": " + describe(method, c) + "; exact says " +
                                  contact_words(contact) + ".",
                              "Shrunk by fdhcert fuzz --toi from family " + family + "."});
  }
  // The id names the direction too (M/F/fp): classify --per-query rows carry it.
  const Verdicts v = check(method, q, contact.hit);
  const std::string d = direction(v);
  QueryRecord named = r;
  named.id += "/" + d;
  return case_file_text(named, {method.name + " says " + (v.said ? "hit" : "no") + ", exact says " +
                                    contact_words(contact) + ": " + direction_words(d) + ".",
                                "Shrunk by fdhcert fuzz from family " + family + "."});
}

std::string class_of_case_file(const std::string& path, bool metamorphic) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dash = name.find('-');
  if (dash != std::string::npos && dash > 0) return name.substr(0, dash);
  return metamorphic ? "metamorphic" : "disagrees";
}

}  // namespace fdh::verify

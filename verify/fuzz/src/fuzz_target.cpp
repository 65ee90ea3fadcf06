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
  return method.applies_to(q) && !check(method, q).agree() ? "disagrees" : "";
}

std::string FuzzTarget::case_folder(const std::string& family) const {
  return (metamorphic ? "metamorphic/" : toi ? "toi/" : "") + method.name + "/" + family;
}

std::string FuzzTarget::case_name(const Query& q) const {
  return (toi ? finding(q) + "-" : "") + case_hash(q) + ".vf";
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
  const Verdicts v = check(method, q, contact.hit);
  return case_file_text(r, {method.name + " says " + (v.said ? "hit" : "no") + ", exact says " +
                                contact_words(contact) + ".",
                            "Shrunk by fdhcert fuzz from family " + family + "."});
}

}  // namespace fdh::verify

// What fuzz looks for, and the case files it writes (fuzz_target.hpp).
#include "fuzz_target.hpp"

#include "fdh/check/checker.hpp"
#include "fdh/check/contact.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/record_scope.hpp"

namespace fdh::verify {

bool FuzzTarget::fails(const Query& q) const {
  if (metamorphic) return metamorphic_failure(method, q).has_value();
  return method.applies_to(q) && !check(method, q).agree();
}

std::string FuzzTarget::case_folder(const std::string& family) const {
  return (metamorphic ? "metamorphic/" : "") + method.name + "/" + family;
}

// The exact contact, computed once, gives the twin's verdict (the case's truth) and its words.
std::string FuzzTarget::case_text(const Query& q, const std::string& family) const {
  const TwinContact contact = twin_contact(q);
  const QueryRecord r{q, case_folder(family), truth_of(contact.hit), "", 0};
  const RecordScope asking(r);
  if (metamorphic) {
    const MetamorphicFailure f = *metamorphic_failure(method, q);
    return case_file_text(r, {describe(method, f) + "; exact says " + contact_words(contact) + ".",
                              "Shrunk by fdhcert fuzz --metamorphic from family " + family + "."});
  }
  const Verdicts v = check(method, q, contact.hit);
  return case_file_text(r, {method.name + " says " + (v.said ? "hit" : "no") + ", exact says " +
                                contact_words(contact) + ".",
                            "Shrunk by fdhcert fuzz from family " + family + "."});
}

}  // namespace fdh::verify

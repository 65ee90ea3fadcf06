// What fuzz looks for, and the case files it writes (fuzz_target.hpp).
#include "fuzz_target.hpp"

#include "fdh/check/checker.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/io/case_files.hpp"

namespace fdh::verify {

std::string exact_contact_words(const Query& q) {
  if (decision_of(q) == Decision::PointTriangle) {
    const exact::PointTriangleContact e =
        exact::point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f());
    if (!e.hit) return "no";
    return std::string("hit (") + exact::to_string(e.kind) + " at t = " + e.time + ")";
  }
  const exact::CcdContact c = exact::ccd(q);
  if (!c.hit) return "no";
  if (c.time_exact()) return "hit (at t = " + c.time_lo + ")";
  return "hit (at t in [" + c.time_lo + ", " + c.time_hi + "])";
}

bool FuzzTarget::fails(const Query& q) const {
  if (metamorphic) return metamorphic_failure(method, q).has_value();
  return method.applies_to(q) && !check(method, q).agree();
}

std::string FuzzTarget::case_folder(const std::string& family) const {
  return (metamorphic ? "metamorphic/" : "") + method.name + "/" + family;
}

std::string FuzzTarget::case_text(Query q, const std::string& family) const {
  q.id = case_folder(family);
  if (metamorphic) {
    const MetamorphicFailure f = *metamorphic_failure(method, q);
    q.truth = twin_hit(q);
    return case_file_text(q, {describe(method, f) + "; exact says " + exact_contact_words(q) + ".",
                              "Shrunk by fdhcert fuzz --metamorphic from family " + family + "."});
  }
  const Verdicts v = check(method, q);
  q.truth = v.twin;
  return case_file_text(q, {method.name + " says " + (v.said ? "hit" : "no") + ", exact says " +
                                exact_contact_words(q) + ".",
                            "Shrunk by fdhcert fuzz from family " + family + "."});
}

}  // namespace fdh::verify

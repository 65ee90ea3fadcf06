#include "fdh/check/checker.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "fdh/exact/ccd.hpp"
#include "fdh/exact/kdop.hpp"

namespace fdh::verify {

bool keeps_promise(Promise promise, bool said, bool twin) {
  switch (promise) {
    case Promise::Exact:
      return said == twin;
    case Promise::Conservative:
      return said || !twin;
    case Promise::None:
      return true;
  }
  return false;
}

Verdicts unanswered(const Method& m, const NoAnswer& e, bool twin) {
  Verdicts v;
  v.twin = twin, v.said = !twin;
  v.no_answer = true, v.limit = e.seconds;
  v.kept = m.promise == Promise::None;
  return v;
}

Verdicts check(const Method& m, const Query& q, bool twin) {
  Verdicts v;
  v.twin = twin;
  v.said = m.is_twin ? twin : m.hit(q);
  v.kept = keeps_promise(m.promise, v.said, v.twin);
  return v;
}

Verdicts check(const Method& m, const Query& q) {
  return check(m, q, twin_hit(q));
}

Verdicts check(const Method& m, const Query& q, Decision d) {
  Verdicts v;
  v.twin = twin_hit(q, d);
  const QueryTest& test = m.test[std::size_t(d)];
  v.said = m.is_twin || !test ? v.twin : test(q);
  v.kept = keeps_promise(m.promise, v.said, v.twin);
  return v;
}

Verdicts check_given(const Method& m, const Query& q, bool said) {
  Verdicts v;
  v.said = said;
  v.twin = twin_hit(q);
  v.kept = keeps_promise(m.promise, v.said, v.twin);
  return v;
}

std::optional<bool> twin_matches_truth(std::optional<bool> truth, bool twin) {
  if (!truth) return std::nullopt;
  return twin == *truth;
}

void CheckTally::add(bool kept, std::size_t index, std::size_t keep) {
  ++checked;
  if (kept) return;
  ++broken;
  if (first_broken.size() < keep) first_broken.push_back(index);
}

CheckTally check_all(const Method& m, const std::vector<Query>& queries,
                     const std::vector<char>& twin) {
  CheckTally t;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    if (!m.applies_to(q)) continue;
    const auto& filter = m.filter[std::size_t(decision_of(q))];
    if (filter && filter(q) != Filtered::Uncertain) ++t.filter_decided;
    t.add(check(m, q, bool(twin[i])).kept, i);
  }
  return t;
}

namespace {

// m's slab directions, one per slab of its k.
const std::vector<Direction>& directions(const BoxMethod& m) {
  if (m.directions.size() * 2 != std::size_t(m.k))
    throw std::invalid_argument("the k-DOP method " + m.name + " (k = " + std::to_string(m.k) +
                                ") has " + std::to_string(m.directions.size()) +
                                " slab directions, not k / 2");
  return m.directions;
}

}  // namespace

int check_box(const BoxMethod& m, const Vec3* pts, std::size_t n) {
  const std::vector<Direction>& dirs = directions(m);
  std::vector<double> lo(dirs.size()), hi(dirs.size());
  m.build(pts, n, lo.data(), hi.data());
  return exact::first_uncontained_slab(dirs, pts, n, lo.data(), hi.data());
}

Verdicts check_overlap(const BoxMethod& m, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const std::vector<Direction>& dirs = directions(m);
  const std::size_t slabs = dirs.size();
  std::vector<double> la(slabs), ha(slabs), lb(slabs), hb(slabs);
  m.build(a.data(), a.size(), la.data(), ha.data());
  m.build(b.data(), b.size(), lb.data(), hb.data());
  Verdicts v;
  v.said = m.overlap(la.data(), ha.data(), lb.data(), hb.data());
  v.twin = exact::kdops_overlap(dirs, a.data(), a.size(), b.data(), b.size());
  v.kept = keeps_promise(m.promise, v.said, v.twin);
  return v;
}

std::vector<std::pair<int, int>> culled_pairs(std::vector<std::pair<int, int>> found,
                                              const std::vector<std::pair<int, int>>& exact) {
  std::sort(found.begin(), found.end());
  std::vector<std::pair<int, int>> culled;
  for (const auto& p : exact)
    if (!std::binary_search(found.begin(), found.end(), p)) culled.push_back(p);
  return culled;
}

Disagreement disagreement_of(bool said, bool twin) {
  if (said == twin) return Disagreement::None;
  return said ? Disagreement::FalseAlarm : Disagreement::Miss;
}

Judgement judge(Promise p, bool said, bool twin) {
  if (said == twin) return Judgement::Kept;
  if (p == Promise::None) return Judgement::Unpromised;
  return keeps_promise(p, said, twin) ? Judgement::Allowed : Judgement::Broken;
}

namespace {

std::string judgement_words(Judgement j, const std::string& broken, const std::string& allowed) {
  switch (j) {
    case Judgement::Kept:
      return "";
    case Judgement::Broken:
      return "(breaks " + broken + ")";
    case Judgement::Allowed:
      return "(allowed: " + allowed + ")";
    case Judgement::Unpromised:
      return "(no promise)";
  }
  return "";
}

}  // namespace

std::string judgement_words(Judgement j, Promise p) {
  std::string upper = to_string(p);
  for (char& ch : upper) ch = char(std::toupper(static_cast<unsigned char>(ch)));
  return judgement_words(j, upper, to_string(p));
}

std::string judgement_words(Judgement j, TimePromise p) {
  return judgement_words(j, to_string(p), to_string(p));
}

namespace {

// "5 s", "0.25 s": a time limit in words.
std::string seconds_words(double s) {
  char text[40];
  std::snprintf(text, sizeof text, "%g s", s);
  return text;
}

std::string broken_words(const Method& m) {
  return judgement_words(Judgement::Broken, m.promise);
}

// What a disagreement is: named as a fault where a promise judges it, plainly where none does.
std::string disagreement_phrase(Promise p, bool said) {
  if (p == Promise::None)
    return said ? "answers hit where exact says no" : "answers no where exact says hit";
  return said ? "gives a false alarm" : "misses a hit";
}

}  // namespace

std::string verdict_words(const Method& m, bool said, bool twin, const std::string& where) {
  const Judgement j = judge(m.promise, said, twin);
  if (j == Judgement::Kept) return "";
  return m.name + " " + disagreement_phrase(m.promise, said) +
         (where.empty() ? "" : " at " + where) + " " + judgement_words(j, m.promise);
}

void DisagreementTally::add(Promise p, bool said, bool twin) {
  const Disagreement d = disagreement_of(said, twin);
  misses += d == Disagreement::Miss, false_alarms += d == Disagreement::FalseAlarm;
  const Judgement j = judge(p, said, twin);
  broken += j == Judgement::Broken, allowed += j == Judgement::Allowed;
}

void DisagreementTally::merge(const DisagreementTally& o) {
  misses += o.misses, false_alarms += o.false_alarms, broken += o.broken, allowed += o.allowed;
}

std::string describe(const Method& m, const Verdicts& v) {
  const auto word = [](bool hit) { return hit ? "hit" : "no"; };
  if (v.no_answer)
    return m.name + " gives no answer in " + seconds_words(v.limit) + ", the exact twin says " +
           word(v.twin) + (m.promise == Promise::None ? " (no promise)" : " " + broken_words(m));
  std::string out = m.name + " says " + word(v.said) + ", the exact twin says " + word(v.twin);
  if (v.said == v.twin) return out;
  if (m.promise == Promise::None) return out + " (no promise)";
  return out + ": " + disagreement_phrase(m.promise, v.said) + " " +
         judgement_words(judge(m.promise, v.said, v.twin), m.promise);
}

TimeTwin time_twin(const Query& q) {
  exact::CcdOptions o;
  o.time_bits = 52;
  const exact::CcdContact c = exact::ccd(q, o);
  TimeTwin t;
  t.hit = c.hit;
  if (c.hit) t.t_star = c.time_lo_down + (c.time_hi_up - c.time_lo_down) / 2;
  return t;
}

bool keeps_time_promise(TimePromise promise, const TimeCheck& c) {
  switch (promise) {
    case TimePromise::Enclosure:
      return !c.no_answer && !c.garbage && !c.verdict_error && !c.late && c.enclosed && !c.too_wide;
    case TimePromise::NeverLate:
      return !c.no_answer && !c.garbage && !c.late;
    case TimePromise::None:
      return true;
  }
  return false;
}

TimeCheck check_time_given(const Method& m, const Query& q, double width, const Toi& said,
                           const TimeTwin& twin) {
  TimeCheck c;
  c.said = said, c.twin = twin, c.width = width;
  c.verdict_error = said.hit != twin.hit;
  if (said.hit) {
    // Written so that NaN is garbage too; t_hi = +inf is no upper bound, not garbage.
    c.garbage =
        !(0 <= said.t_lo && said.t_lo <= said.t_hi && (said.t_hi <= 1 || no_upper_bound(said)));
    c.too_wide = !c.garbage && said.t_hi - said.t_lo > width;
  }
  if (twin.hit && !said.hit) c.late = true;  // a missed contact: the step passes through
  if (twin.hit && said.hit && !c.garbage) {
    const int lo = exact::compare_with_toi(q, said.t_lo);
    c.late = lo > 0;
    c.enclosed = lo <= 0 && (no_upper_bound(said) || exact::compare_with_toi(q, said.t_hi) >= 0);
    c.zero = said.t_lo == 0 && lo < 0;
    c.early = c.late ? 0 : std::max(0.0, twin.t_star - said.t_lo);
  }
  c.kept = keeps_time_promise(m.time_promise, c);
  return c;
}

TimeCheck check_time(const Method& m, const Query& q, double width, const TimeTwin& twin) {
  return check_time_given(m, q, width, m.time_of_impact(q, width), twin);
}

TimeCheck unanswered_time(const Method& m, const NoAnswer& e, double width, const TimeTwin& twin) {
  TimeCheck c;
  c.twin = twin, c.width = width;
  c.no_answer = true, c.limit = e.seconds;
  c.kept = m.time_promise == TimePromise::None;
  return c;
}

bool no_upper_bound(const Toi& t) {
  return t.t_hi == std::numeric_limits<double>::infinity();
}

TimeCheck check_time(const Method& m, const Query& q, double width) {
  return check_time(m, q, width, time_twin(q));
}

void TimeTally::add(const TimeCheck& c, std::size_t index, std::size_t keep) {
  ++checked;
  contacts += c.twin.hit;
  verdict_errors += c.verdict_error, late += c.late, zero += c.zero;
  not_enclosed += !c.enclosed, too_wide += c.too_wide, garbage += c.garbage;
  no_answer += c.no_answer;
  if (c.twin.hit && c.said.hit && !c.late && !c.garbage) early.push_back(c.early);
  if (c.kept) return;
  ++broken;
  if (first_broken.size() < keep) first_broken.push_back(index);
}

void TimeTally::merge(const TimeTally& o, std::size_t offset) {
  checked += o.checked, contacts += o.contacts, verdict_errors += o.verdict_errors;
  late += o.late, zero += o.zero, not_enclosed += o.not_enclosed, too_wide += o.too_wide;
  garbage += o.garbage, no_answer += o.no_answer, broken += o.broken;
  early.insert(early.end(), o.early.begin(), o.early.end());
  for (const std::size_t i : o.first_broken)
    if (first_broken.size() < 16) first_broken.push_back(offset + i);
}

double TimeTally::early_max() const {
  return early.empty() ? 0 : *std::max_element(early.begin(), early.end());
}

double TimeTally::early_median() const {
  if (early.empty()) return 0;
  std::vector<double> e = early;
  const auto mid = e.begin() + std::ptrdiff_t((e.size() - 1) / 2);
  std::nth_element(e.begin(), mid, e.end());
  return *mid;
}

namespace {

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

}  // namespace

std::string describe(const Method& m, const TimeCheck& c) {
  const std::string enclosure = "[" + number(c.said.t_lo) + ", " + number(c.said.t_hi) + "]";
  const std::string t_star = "t* ~ " + number(c.twin.t_star);
  if (c.no_answer) return m.name + " gives no answer in " + seconds_words(c.limit);
  if (c.garbage)
    return m.name + "'s TOI " + enclosure + " is not a time (not 0 <= t_lo <= t_hi <= 1)";
  if (c.late && !c.said.hit)
    return m.name + " says no contact, the exact twin finds one at " + t_star;
  if (c.late) return m.name + "'s TOI is late: t_lo = " + number(c.said.t_lo) + " > " + t_star;
  if (c.verdict_error)
    return m.name + " says contact at " + enclosure + ", the exact twin says none";
  if (!c.enclosed) return m.name + "'s enclosure " + enclosure + " misses " + t_star;
  if (c.too_wide) return m.name + "'s enclosure " + enclosure + " is wider than " + number(c.width);
  if (c.zero) return m.name + "'s TOI is 0, " + t_star;
  if (c.early > 0)
    return m.name + "'s TOI is early by " + number(c.early) + " of the step, " + t_star;
  return "";
}

Judgement judge(const Method& m, const TimeCheck& c) {
  if (!c.kept) return Judgement::Broken;
  if (describe(m, c).empty()) return Judgement::Kept;
  return m.time_promise == TimePromise::None ? Judgement::Unpromised : Judgement::Allowed;
}

std::string judged_time_words(const Method& m, const TimeCheck& c) {
  const Judgement j = judge(m, c);
  if (j == Judgement::Kept) return "";
  // A kept never-late promise says nothing of the verdict or the enclosure: its words name what
  // it does speak of, how early.
  TimeCheck spoken = c;
  if (j == Judgement::Allowed && m.time_promise == TimePromise::NeverLate)
    spoken.verdict_error = false, spoken.enclosed = true, spoken.too_wide = false;
  const std::string words = describe(m, spoken);
  return (words.empty() ? describe(m, c) : words) + " " + judgement_words(j, m.time_promise);
}

}  // namespace fdh::verify

#include "fdh/check/checker.hpp"

#include <algorithm>
#include <stdexcept>

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

std::string describe(const Method& m, const Verdicts& v) {
  const auto word = [](bool hit) { return hit ? "hit" : "no"; };
  return m.name + " says " + word(v.said) + ", the exact twin says " + word(v.twin);
}

}  // namespace fdh::verify

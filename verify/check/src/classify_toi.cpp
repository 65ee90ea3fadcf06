#include "fdh/check/classify_toi.hpp"

#include "fdh/check/classify.hpp"
#include "fdh/check/parallel.hpp"

namespace fdh::verify {
namespace {

// m's times on every query it gives one for, timed on this thread.
ToiResult run_and_time(const Method& m, const std::vector<Query>& qs, double width,
                       const ProgressSink& progress) {
  ToiResult r;
  r.name = m.name;
  r.promise = m.time_promise;
  r.said.assign(qs.size(), Toi{});
  r.applies.assign(qs.size(), 0);
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < qs.size(); ++i)
    if (m.gives_toi(qs[i])) mine.push_back(i), r.applies[i] = 1;
  r.na = long(qs.size() - mine.size());
  PassProgress told{progress, "classify --toi " + m.name, long(mine.size())};
  const double seconds = seconds_per_pass([&] {
    for (std::size_t k = 0; k < mine.size(); ++k)
      told.at(k), r.said[mine[k]] = m.time_of_impact(qs[mine[k]], width);
    told.first = false;
  });
  r.ns_per_query = mine.empty() ? 0 : seconds * 1e9 / double(mine.size());
  return r;
}

}  // namespace

ToiClassification classify_toi(const std::vector<Query>& queries,
                               const std::vector<Method>& methods, double width,
                               const ProgressSink& progress) {
  ToiClassification c;
  c.width = width;
  c.queries = queries.size();
  c.twin.resize(queries.size());
  // The twin and the checks, untimed, on every core; the methods are timed on this thread.
  for_each_index(queries.size(), 16, [&](std::size_t i) { c.twin[i] = time_twin(queries[i]); });
  for (const Method& m : methods) {
    if (!m.toi[0] && !m.toi[1]) continue;
    ToiResult r = run_and_time(m, queries, width, progress);
    r.checks.resize(queries.size());
    for_each_index(queries.size(), 16, [&](std::size_t i) {
      if (r.applies[i]) r.checks[i] = check_time_given(m, queries[i], width, r.said[i], c.twin[i]);
    });
    for (std::size_t i = 0; i < queries.size(); ++i)
      if (r.applies[i]) r.tally.add(r.checks[i], i);
    c.methods.push_back(std::move(r));
  }
  return c;
}

ToiClassification join(const std::vector<ToiClassification>& parts) {
  ToiClassification all;
  for (const ToiClassification& c : parts) {
    const std::size_t offset = all.queries;
    all.width = c.width;
    all.queries += c.queries;
    all.twin.insert(all.twin.end(), c.twin.begin(), c.twin.end());
    if (all.methods.empty())
      for (const ToiResult& m : c.methods)
        all.methods.push_back({m.name, m.promise, 0, 0, {}, {}, {}, {}});
    for (std::size_t k = 0; k < c.methods.size(); ++k) {
      ToiResult& t = all.methods[k];
      const ToiResult& u = c.methods[k];
      const double given_t = double(t.said.size()) - double(t.na);
      const double given_u = double(u.said.size()) - double(u.na);
      const double time = t.ns_per_query * given_t + u.ns_per_query * given_u;
      t.ns_per_query = given_t + given_u > 0 ? time / (given_t + given_u) : 0;
      t.na += u.na;
      t.tally.merge(u.tally, offset);
      t.said.insert(t.said.end(), u.said.begin(), u.said.end());
      t.applies.insert(t.applies.end(), u.applies.begin(), u.applies.end());
      t.checks.insert(t.checks.end(), u.checks.begin(), u.checks.end());
    }
  }
  return all;
}

}  // namespace fdh::verify

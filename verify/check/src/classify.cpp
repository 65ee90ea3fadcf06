#include "fdh/check/classify.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "fdh/check/checker.hpp"
#include "fdh/check/parallel.hpp"

namespace fdh::verify {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<char> run_and_time(const Method& m, const std::vector<Query>& qs, double& ns_per_query,
                               const ProgressSink& progress) {
  std::vector<char> verdict(qs.size(), kNotApplicable);
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < qs.size(); ++i)
    if (m.applies_to(qs[i])) mine.push_back(i);
  PassProgress told{progress, "classify " + m.name, long(mine.size())};
  const double seconds = seconds_per_pass([&] {
    for (std::size_t k = 0; k < mine.size(); ++k) told.at(k), verdict[mine[k]] = m.hit(qs[mine[k]]);
    told.first = false;
  });
  ns_per_query = mine.empty() ? 0 : seconds * 1e9 / double(mine.size());
  return verdict;
}

}  // namespace

double seconds_per_pass(const std::function<void()>& pass) {
  const auto seconds = [](Clock::time_point a) {
    return std::chrono::duration<double>(Clock::now() - a).count();
  };
  auto start = Clock::now();
  pass();
  double elapsed = seconds(start);
  long passes = 1;
  const double target = 0.02;
  if (elapsed < target) {
    passes = std::min(1000L, long(std::ceil(target / std::max(elapsed, 1e-7))));
    start = Clock::now();
    for (long p = 0; p < passes; ++p) pass();
    elapsed = seconds(start);
  }
  return elapsed / double(passes);
}

const char* truth_source_name(TruthSource s) {
  switch (s) {
    case TruthSource::File:
      return "file";
    case TruthSource::Exact:
      return "exact";
    case TruthSource::Mixed:
      return "mixed";
  }
  return "mixed";
}

Classification classify(const std::vector<Query>& queries,
                        const std::vector<std::optional<bool>>& truth,
                        const std::vector<Method>& methods, const ProgressSink& progress) {
  if (!truth.empty() && truth.size() != queries.size())
    throw std::invalid_argument("classify: one truth per query, or none");
  Classification c;
  c.queries = queries.size();

  c.exact.resize(queries.size());
  // The twin, untimed, on every core; the methods below are timed one at a time on this thread.
  for_each_index(queries.size(), 16, [&](std::size_t i) { c.exact[i] = twin_hit(queries[i]); });
  for (const Query& q : queries) {
    ++(q.is_static_vf()                  ? c.static_vf
       : q.kind == QueryKind::VertexFace ? c.moving_vf
                                         : c.edge_edge);
  }

  std::size_t with_truth = 0;
  c.reference.resize(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const std::optional<bool> given = truth.empty() ? std::nullopt : truth[i];
    if (given) {
      ++with_truth;
      c.reference[i] = char(*given);
    } else {
      c.reference[i] = c.exact[i];
    }
  }
  c.truth = with_truth == queries.size() ? TruthSource::File
            : with_truth == 0            ? TruthSource::Exact
                                         : TruthSource::Mixed;

  for (const Method& m : methods) {
    MethodResult r;
    r.name = m.name;
    r.promise = m.promise;
    r.verdict = run_and_time(m, queries, r.tally.ns_per_query, progress);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (r.verdict[i] == kNotApplicable) {
        ++r.tally.na;
        continue;
      }
      const bool v = r.verdict[i], t = c.reference[i];
      (v ? (t ? r.tally.tp : r.tally.fp) : (t ? r.tally.fn : r.tally.tn))++;
      r.against_exact.add(m.promise, v, c.exact[i]);
    }
    c.methods.push_back(std::move(r));
  }
  return c;
}

Classification join(const std::vector<Classification>& parts) {
  Classification all;
  bool truth_set = false;
  for (const Classification& c : parts) {
    all.queries += c.queries;
    all.static_vf += c.static_vf, all.moving_vf += c.moving_vf, all.edge_edge += c.edge_edge;
    all.truth = !truth_set || all.truth == c.truth ? c.truth : TruthSource::Mixed;
    truth_set = true;
    all.reference.insert(all.reference.end(), c.reference.begin(), c.reference.end());
    all.exact.insert(all.exact.end(), c.exact.begin(), c.exact.end());
    if (all.methods.empty())
      for (const MethodResult& m : c.methods)
        all.methods.push_back({m.name, {}, {}, m.promise, {}});
    for (std::size_t k = 0; k < c.methods.size(); ++k) {
      Tally& t = all.methods[k].tally;
      const Tally& u = c.methods[k].tally;
      const double time =
          t.ns_per_query * double(t.decided()) + u.ns_per_query * double(u.decided());
      t.tp += u.tp, t.tn += u.tn, t.fp += u.fp, t.fn += u.fn, t.na += u.na;
      t.ns_per_query = t.decided() ? time / double(t.decided()) : 0;
      all.methods[k].against_exact.merge(c.methods[k].against_exact);
      auto& v = all.methods[k].verdict;
      v.insert(v.end(), c.methods[k].verdict.begin(), c.methods[k].verdict.end());
    }
  }
  return all;
}

}  // namespace fdh::verify

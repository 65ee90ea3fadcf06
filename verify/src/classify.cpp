#include "fdh/verify/classify.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fdh::verify {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<char> run_and_time(const Method& m, const std::vector<Query>& qs,
                               double& ns_per_query) {
  std::vector<char> verdict(qs.size());
  const auto pass = [&] {
    for (std::size_t i = 0; i < qs.size(); ++i) verdict[i] = m.hit(qs[i]);
  };
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
  ns_per_query = qs.empty() ? 0 : elapsed * 1e9 / (double(passes) * double(qs.size()));
  return verdict;
}

}  // namespace

Classification classify(const std::vector<Query>& queries, const std::vector<Method>& methods) {
  Classification c;
  c.queries = queries.size();

  const Method* exact = nullptr;
  const std::vector<Method> all = all_methods();
  for (const Method& m : methods)
    if (m.name == "exact") exact = &m;
  if (!exact) exact = &all.front();
  c.exact.resize(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) c.exact[i] = exact->hit(queries[i]);

  std::size_t with_truth = 0;
  c.reference.resize(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    if (q.has_truth()) {
      ++with_truth;
      c.reference[i] = char(q.truth);
      if (q.truth != c.exact[i]) c.exact_vs_file.push_back(i);
    } else {
      c.reference[i] = c.exact[i];
    }
  }
  c.truth = with_truth == queries.size() ? "file" : (with_truth == 0 ? "exact" : "mixed");

  for (const Method& m : methods) {
    MethodResult r;
    r.name = m.name;
    r.verdict = run_and_time(m, queries, r.tally.ns_per_query);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const bool v = r.verdict[i], t = c.reference[i];
      (v ? (t ? r.tally.tp : r.tally.fp) : (t ? r.tally.fn : r.tally.tn))++;
    }
    c.methods.push_back(std::move(r));
  }
  return c;
}

}  // namespace fdh::verify

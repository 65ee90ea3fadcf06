#include <algorithm>
#include <sstream>
#include <vector>

#include "fdh/check/classify.hpp"
#include "fdh/gen/static_families.hpp"
#include "fdh/suite/fuzz.hpp"
#include "fdh/suite/measurements.hpp"

namespace fdh::verify {

std::string speed_accuracy_csv(long per_family, std::uint64_t seed) {
  std::ostringstream os;
  os << "method,family,queries,ns_per_query,fp_rate,fn_rate\n";
  const std::vector<Method> methods = all_methods();
  std::uint64_t stream = 0;
  for (const Family f : all_families()) {
    ++stream;
    std::vector<Query> qs;
    for (long i = 0; i < per_family; ++i) {
      Query q = gen_family(f)(rc::Random(case_seed(seed * 1000 + stream, i))).value().query;
      q.truth = -1;  // count against exact
      qs.push_back(q);
    }
    const Classification c = classify(qs, methods);
    for (const MethodResult& m : c.methods)
      os << m.name << ',' << family_name(f) << ',' << qs.size() << ',' << m.tally.ns_per_query
         << ',' << double(m.tally.fp) / double(qs.size()) << ','
         << double(m.tally.fn) / double(qs.size()) << '\n';
  }
  return os.str();
}

std::string pareto_csv(const std::string& speed_accuracy) {
  struct Point {
    std::string method, family;
    double ns, err;
  };
  std::vector<Point> pts;
  std::istringstream in(speed_accuracy);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    Point p;
    std::string n, ns, fp, fn;
    std::getline(ls, p.method, ',');
    std::getline(ls, p.family, ',');
    std::getline(ls, n, ',');
    std::getline(ls, ns, ',');
    std::getline(ls, fp, ',');
    std::getline(ls, fn, ',');
    p.ns = std::stod(ns);
    p.err = std::stod(fp) + std::stod(fn);
    pts.push_back(p);
  }
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) {
    return a.ns < b.ns || (a.ns == b.ns && a.err < b.err);
  });
  std::ostringstream os;
  os << "method,family,ns_per_query,error_rate\n";
  double best = 2;
  for (const Point& p : pts)
    if (p.err < best) {
      best = p.err;
      os << p.method << ',' << p.family << ',' << p.ns << ',' << p.err << '\n';
    }
  return os.str();
}

}  // namespace fdh::verify

// Which methods answer right as a query's true least distance approaches the minimum separation
// D from both sides (issue 30): queries whose least Euclidean distance is H = D·(1 + s) exactly,
// by construction, asked at δ = D, for s = ±2^-p.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {
namespace {

// Dyadic doubles of few bits (multiples of 2^-10), so that every coordinate below that carries
// no H is a double exactly, and one that carries H is H itself, -H or H plus such a number
// within 53 bits (H has at most 52 bits below D's, none above it).
class Dyadic {
 public:
  explicit Dyadic(std::uint64_t seed) : rng_(seed) {}
  double in(double lo, double hi) {  // a multiple of 2^-10 in [lo, hi]
    std::uniform_int_distribution<long> n(long(std::ceil(lo * 1024)), long(std::floor(hi * 1024)));
    return std::ldexp(double(n(rng_)), -10);
  }
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

 private:
  std::mt19937_64 rng_;
};

// The configurations, each at least H apart at every time and exactly H apart at some (the
// distance is measured along z or y, where the other primitive's coordinates are 0):
Query over_face(Dyadic& r, double h) {  // the point slides H above the face's interior
  const double a = r.in(0.5, 1), b = r.in(0.5, 1), u = r.in(0, 0.4), v = r.in(0, 0.4);
  const Vec3 d{0, 0, 0}, e{a, 0, 0}, f{0, b, 0}, drift{r.in(-1, 1), r.in(-1, 1), 0};
  Query q;
  q.x = {Vec3{u * a, v * b, h}, d, e, f, Vec3{r.in(-1, 1), r.in(-1, 1), h}, d, e, f};
  if (r.below(2))  // the triangle moves too, in its plane: a moving query
    for (int i = 5; i < 8; ++i) q.x[std::size_t(i)] = q.x[std::size_t(i)] + drift;
  return q;
}
Query beside_edge(Dyadic& r, double h) {  // H from the edge on the x axis, rising away in z
  const double a = r.in(0.5, 1), b = r.in(0.5, 1), x = r.in(0, 0.5);
  const Vec3 d{0, 0, 0}, e{a, 0, 0}, f{r.in(0, 1), b, 0};
  Query q;
  q.x = {Vec3{x, -h, 0}, d, e, f, Vec3{r.in(-1, 1), -h, r.in(0, 1)}, d, e, f};
  return q;
}
Query beyond_corner(Dyadic& r, double h) {  // H from the corner at the origin, leaving it
  const Vec3 d{0, 0, 0}, e{r.in(0.5, 1), 0, 0}, f{0, r.in(0.5, 1), 0};
  Query q;
  q.x = {Vec3{-h, 0, 0}, d, e, f, Vec3{-h, -r.in(0, 1), r.in(-1, 1)}, d, e, f};
  return q;
}
Query parallel_edges(Dyadic& r, double h) {  // along x, H apart in z, sliding along each other
  const double l = r.in(0.5, 1), s = r.in(-0.25, 0.25);
  Query q;
  q.kind = QueryKind::EdgeEdge;
  q.x = {Vec3{0, 0, 0},
         Vec3{l, 0, 0},
         Vec3{s, 0, h},
         Vec3{s + l, 0, h},
         Vec3{0, 0, 0},
         Vec3{l, 0, 0},
         Vec3{s + r.in(0, 1), 0, h},
         Vec3{s + l + r.in(0, 1), 0, h}};
  q.x[7].x = q.x[6].x + l;
  return q;
}
Query crossing_edges(Dyadic& r, double h) {  // x and y edges H apart in z, crossing at t = 0
  const double c = r.in(-0.5, 0.5);
  Query q;
  q.kind = QueryKind::EdgeEdge;
  q.x = {Vec3{-1, 0, 0}, Vec3{1, 0, 0}, Vec3{c, -1, h},  Vec3{c, 1, h},
         Vec3{-1, 0, 0}, Vec3{1, 0, 0}, Vec3{c, 0.5, h}, Vec3{c, 2, h}};
  q.x[6].x = q.x[7].x = r.in(-3, 3);  // it may slide off the end: still H at t = 0
  return q;
}

// The i-th query of a point, its axes permuted (an exact transform of every distance).
Query at_distance(Dyadic& r, long i, double h) {
  static Query (*const make[])(Dyadic&, double) = {over_face, beside_edge, beyond_corner,
                                                   parallel_edges, crossing_edges};
  Query q = make[i % 5](r, h);
  const int k = r.below(3);
  for (Vec3& p : q.x)
    for (int j = 0; j < k; ++j) p = Vec3{p.y, p.z, p.x};
  return q;
}

}  // namespace

const std::vector<int>& min_distance_stability_steps() {
  static const std::vector<int> p = {10, 15, 20, 25, 30, 35, 40, 45, 50};
  return p;
}

std::vector<MinDistanceStabilityRow> min_distance_stability(long per_point, std::uint64_t seed,
                                                            const ProgressSink& progress) {
  const double d = kMinDistanceStabilityD;
  std::vector<std::pair<int, int>> points{{0, 0}};  // (side, p): side -1 below D, +1 above
  for (const int p : min_distance_stability_steps())
    points.push_back({-1, p}), points.push_back({1, p});
  std::vector<MinDistanceStabilityRow> rows;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const auto [side, p] = points[n];
    report(progress, {"minimum separation: stability", long(n), long(points.size()), "points"});
    const double h = side == 0 ? d : d + side * std::ldexp(d, -p);  // exact: p <= 52
    Dyadic r(seed * 7919 + std::uint64_t(n));
    std::vector<Query> qs;
    for (long i = 0; i < per_point; ++i) qs.push_back(at_distance(r, i, h));
    for (Query& q : qs) q.min_distance = d;
    for (const Method& m : all_methods()) {
      long asked = 0, wrong = 0;
      for (const Query& q : qs) {
        if (!m.applies_to(q)) continue;
        ++asked;
        wrong += m.hit(q) != (side <= 0);  // within D iff H <= D
      }
      if (asked > 0) rows.push_back({side, p, m.name, asked, double(wrong) / double(asked)});
    }
  }
  return rows;
}

std::string min_distance_stability_csv(const std::vector<MinDistanceStabilityRow>& rows) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out), "side,p,x,method,queries,failure_rate\n");
  for (const MinDistanceStabilityRow& r : rows)
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{:.6g}\n", r.side, r.p, r.x(), r.method,
                   r.queries, r.failure_rate);
  return fmt::to_string(out);
}

}  // namespace fdh::verify

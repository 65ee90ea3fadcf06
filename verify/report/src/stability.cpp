// Where methods break: failure rates as one parameter of the query goes to its degenerate
// limit; and, on the sweeps whose contacts turn grazing, the methods' times of impact.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>

#include "fdh/check/checker.hpp"
#include "fdh/check/parallel.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {
namespace {

// Plain doubles (rounding included): the rates are against exact on the doubles as they are.
class Sampler {
 public:
  explicit Sampler(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  Vec3 point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
  Vec3 unit() {
    for (;;) {
      const Vec3 v = point(1);
      const double n = norm(v);
      if (n > 0.1 && n <= 1) return (1 / n) * v;
    }
  }
  bool coin() { return uniform(0, 1) < 0.5; }

 private:
  std::mt19937_64 rng_;
};

Vec3 unit(const Vec3& v) {
  return (1 / norm(v)) * v;
}

struct Tri3 {
  Vec3 d, e, f;
  Vec3 n() const { return unit(cross(e - d, f - d)); }
  Vec3 at(double a, double b) const { return d + a * (e - d) + b * (f - d); }
};

Tri3 triangle(Sampler& s) {
  for (;;) {
    const Tri3 t{s.point(1), s.point(1), s.point(1)};
    if (norm(cross(t.e - t.d, t.f - t.d)) > 0.1) return t;
  }
}

Query make(const Tri3& t, const Vec3& b0, const Vec3& b1) {
  Query q;
  q.x = {b0, t.d, t.e, t.f, b1, t.d, t.e, t.f};
  return q;
}

// A path through X, from above the plane to below it.
Query through(Sampler& s, const Tri3& t, const Vec3& x) {
  const Vec3 dir = s.uniform(0.2, 1) * t.n() + s.uniform(-0.5, 0.5) * unit(t.e - t.d);
  return make(t, x + dir, x - s.uniform(0.2, 1) * dir);
}

Query angle_query(int p, Sampler& s) {
  const Tri3 t = triangle(s);
  const Vec3 x = t.at(s.uniform(-0.25, 1.25), s.uniform(-0.25, 1.25));
  const Vec3 along = unit(t.e - t.d);
  const double tiny = std::ldexp(1.0, -p);
  const Vec3 dir = std::cos(tiny) * along - std::sin(tiny) * t.n();
  return make(t, x - s.uniform(0.1, 1) * dir, x + s.uniform(0.1, 1) * dir);
}

Query edge_query(int p, Sampler& s) {
  const Tri3 t = triangle(s);
  const Vec3 v[3] = {t.d, t.e, t.f};
  const int i = int(s.uniform(0, 3)) % 3;
  const Vec3 a = v[i], b = v[(i + 1) % 3];
  const Vec3 out = unit(cross(b - a, t.n()));
  const double tiny = std::ldexp(1.0, -p);
  const Vec3 x = a + s.uniform(0.05, 0.95) * (b - a) + (s.coin() ? tiny : -tiny) * out;
  return through(s, t, x);
}

Query magnitude_query(int p, Sampler& s) {
  const Tri3 t0 = triangle(s);
  const Query q = through(s, t0, t0.at(s.uniform(-0.25, 1.25), s.uniform(-0.25, 1.25)));
  const Vec3 shift =
      std::ldexp(1.0, p) * Vec3{s.uniform(0.5, 1), -s.uniform(0.5, 1), s.uniform(0.5, 1)};
  Query moved = q;
  for (Vec3& x : moved.x) x += shift;
  return moved;
}

// F lies 2^-p |DE| off the line DE.
Query aspect_query(int p, Sampler& s) {
  Tri3 t{s.point(1), s.point(1), {}};
  const double len = norm(t.e - t.d);
  const Vec3 off = unit(cross(t.e - t.d, s.unit()));
  t.f = t.d + s.uniform(-0.25, 1.25) * (t.e - t.d) + (std::ldexp(1.0, -p) * len) * off;
  const Vec3 x = t.at(s.uniform(-0.25, 1.25), s.uniform(-0.25, 1.25));
  const Vec3 up = cross(t.e - t.d, off);  // the plane's normal, computed without F
  const Vec3 dir = s.uniform(0.2, 1) * unit(up) + s.uniform(-0.5, 0.5) * unit(t.e - t.d);
  return make(t, x + dir, x - s.uniform(0.2, 1) * dir);
}

// A dyadic value m/16 with m in [lo, hi]: products of two stay exact.
double sixteenths(Sampler& s, int lo, int hi) {
  return std::floor(s.uniform(lo, hi + 1)) / 16;
}

// The axes permuted and flipped at random, and a dyadic shift: exact, so the tiny offsets the
// constructions below place survive.
Query shuffled(Query q, Sampler& s) {
  int axis[3] = {0, 1, 2};
  std::shuffle(axis, axis + 3, std::mt19937_64(std::uint64_t(s.uniform(0, 1) * 1e18)));
  const double sign[3] = {s.coin() ? 1.0 : -1.0, s.coin() ? 1.0 : -1.0, s.coin() ? 1.0 : -1.0};
  const double shift[3] = {sixteenths(s, -16, 16), sixteenths(s, -16, 16), sixteenths(s, -16, 16)};
  for (Vec3& x : q.x) {
    const Vec3 v = x;
    x = {sign[0] * v[axis[0]] + shift[0], sign[1] * v[axis[1]] + shift[1],
         sign[2] * v[axis[2]] + shift[2]};
  }
  return q;
}

// D and E stay on y = -1, z = 0 while F(t) = (0, 1, 2k(t - 1/2)) tilts the plane about DE; the
// plane's height over P is then k (t - 1/2) (c + k (t - 1/2)), and P's height
// c k (t - 1/2) + eps, so P's signed distance is eps - k^2 (t - 1/2)^2 (times a positive
// factor): a double root at t = 1/2 when eps = 0. eps = +2^-p dips through the face and
// back (inside: P passes (x, c - 1) at t = 1/2); eps = -2^-p misses by 2^-p. P's heights
// are about 1/2, so past p = 53 eps rounds away and the dip is an exact tangency.
Query tangency_query(int p, Sampler& s) {
  const double k = sixteenths(s, 8, 16), c = sixteenths(s, 12, 20);
  const double x = sixteenths(s, -4, 4), eps = (s.coin() ? 1 : -1) * std::ldexp(1.0, -p);
  const double width = sixteenths(s, 16, 24);
  Query q;
  q.x = {Vec3{x, -1 + c - k / 2, -c * k / 2 + eps},
         Vec3{-width, -1, 0},
         Vec3{width, -1, 0},
         Vec3{0, 1, -k},
         Vec3{x, -1 + c + k / 2, c * k / 2 + eps},
         Vec3{-width, -1, 0},
         Vec3{width, -1, 0},
         Vec3{0, 1, k}};
  return shuffled(q, s);
}

// Every point a dyadic height within 2^-p of z = 0 at both ends, while P sweeps across the
// triangle's edge and the triangle slides: the coplanarity cubic's coefficients are all of the
// order of 2^-p.
Query coplanar_query(int p, Sampler& s) {
  const double eps = std::ldexp(1.0, -p);
  const auto z = [&] { return sixteenths(s, -16, 16) * eps; };
  const auto xy = [&](int lo, int hi) { return sixteenths(s, lo, hi); };
  const Vec3 slide{(s.coin() ? 1 : -1) * xy(1, 4), xy(-4, 4), 0};  // never still: a CCD query
  Query q;
  q.x[1] = {-1, -1, z()};
  q.x[2] = {1, -1, z()};
  q.x[3] = {0, 1, z()};
  for (int i = 1; i < 4; ++i) q.x[i + 4] = q.x[i] + slide + Vec3{0, 0, z() - q.x[i].z};
  q.x[0] = {xy(-24, 24), xy(-40, -20), z()};  // below the edge DE
  q.x[4] = {xy(-24, 24), xy(-12, 8), z()};    // across it, inside the slid triangle or not
  return shuffled(q, s);
}

// Every sweep with the construction of its queries.
struct SweepDef {
  StabilitySweep sweep;
  Query (*make)(int p, Sampler& s);
};

const std::vector<SweepDef>& sweep_defs() {
  static const std::vector<SweepDef> defs = {
      {{"angle", 60, "motion-to-plane angle 2^{-p}: p"}, angle_query},
      {{"edge", 64, "distance of the crossing from an edge 2^{-p}: p"}, edge_query},
      {{"magnitude", 40, "distance from the origin 2^{p}: p"}, magnitude_query},
      {{"aspect", 60, "triangle height / base 2^{-p}: p"}, aspect_query},
      {{"tangency", 56, "moving: depth of a tangential dip 2^{-p}: p"}, tangency_query},
      {{"coplanar", 60, "moving: distance of all four points from one plane 2^{-p}: p"},
       coplanar_query}};
  return defs;
}

// What one value p of a sweep counts per method: the queries it applies to and gets wrong.
struct PointCounts {
  std::vector<long> wrong, applied;
};

// per_point queries at p, from their own stream: the same queries on any thread, and the same
// for the verdicts and the times of impact.
std::vector<Query> point_queries(const SweepDef& def, int p, long per_point, std::uint64_t seed) {
  Sampler s(seed * 7919 + std::uint64_t(p) * 131 + std::uint64_t(def.sweep.name[0]));
  std::vector<Query> qs;
  for (long i = 0; i < per_point; ++i) qs.push_back(def.make(p, s));
  return qs;
}

PointCounts point_counts(const SweepDef& def, const std::vector<Method>& methods, int p,
                         long per_point, std::uint64_t seed) {
  PointCounts n{std::vector<long>(methods.size()), std::vector<long>(methods.size())};
  for (const Query& q : point_queries(def, p, per_point, seed)) {
    const bool twin = twin_hit(q);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      if (!methods[m].applies_to(q)) continue;
      const Verdicts v = check(methods[m], q, twin);
      n.wrong[m] += v.said != v.twin;
      ++n.applied[m];
    }
  }
  return n;
}

// failure[m][p]: the share of the queries of each p that methods[m] applies to and gets
// wrong; empty for a method that applies to none of the sweep's queries. The values of p run
// on every core (check/parallel.hpp).
std::vector<std::vector<double>> sweep_rates(const SweepDef& def,
                                             const std::vector<Method>& methods, long per_point,
                                             std::uint64_t seed) {
  const StabilitySweep& sw = def.sweep;
  const auto points = parts_in_order(std::size_t(sw.last) + 1, 1, PointCounts{},
                                     [&](std::size_t p, std::size_t, PointCounts& n) {
                                       n = point_counts(def, methods, int(p), per_point, seed);
                                     });
  std::vector<std::vector<double>> failure(methods.size(), std::vector<double>(sw.last + 1));
  std::vector<long> applied_in_sweep(methods.size());
  for (std::size_t p = 0; p < points.size(); ++p)
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const long applied = points[p].applied[m];
      failure[m][p] = applied ? double(points[p].wrong[m]) / double(applied) : 0;
      applied_in_sweep[m] += applied;
    }
  for (std::size_t m = 0; m < methods.size(); ++m)
    if (applied_in_sweep[m] == 0) failure[m].clear();
  return failure;
}

// The TOI checks of each method at p: tallies[m], against the twin's t*, untimed.
std::vector<TimeTally> toi_point(const SweepDef& def, const std::vector<Method>& methods, int p,
                                 long per_point, std::uint64_t seed) {
  const std::vector<Query> qs = point_queries(def, p, per_point, seed);
  std::vector<TimeTally> tallies(methods.size());
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const TimeTwin twin = time_twin(qs[i]);
    for (std::size_t m = 0; m < methods.size(); ++m)
      if (methods[m].gives_toi(qs[i]))
        tallies[m].add(check_time(methods[m], qs[i], kToiWidthAsked, twin), i);
  }
  return tallies;
}

bool is_toi_sweep(const SweepDef& def) {
  const std::string name = def.sweep.name;
  return name == "angle" || name == "edge" || name == "tangency";
}

}  // namespace

const std::vector<StabilitySweep>& toi_stability_sweeps() {
  static const std::vector<StabilitySweep> sweeps = [] {
    std::vector<StabilitySweep> out;
    for (const SweepDef& d : sweep_defs())
      if (is_toi_sweep(d)) out.push_back(d.sweep);
    return out;
  }();
  return sweeps;
}

std::vector<ToiStabilityRow> toi_stability(long per_point, std::uint64_t seed,
                                           const ProgressSink& progress) {
  std::vector<Method> methods = toi_methods();
  methods.erase(
      std::remove_if(methods.begin(), methods.end(), [](const Method& m) { return m.is_twin; }),
      methods.end());
  std::vector<ToiStabilityRow> rows;
  long done = 0;
  for (const SweepDef& def : sweep_defs()) {
    if (!is_toi_sweep(def)) continue;
    const StabilitySweep& sw = def.sweep;
    report(progress, {"TOI sweeps", done++, long(toi_stability_sweeps().size()), "sweeps"});
    const auto points = parts_in_order(std::size_t(sw.last) + 1, 1, std::vector<TimeTally>{},
                                       [&](std::size_t p, std::size_t, std::vector<TimeTally>& t) {
                                         t = toi_point(def, methods, int(p), per_point, seed);
                                       });
    for (std::size_t m = 0; m < methods.size(); ++m)
      for (std::size_t p = 0; p < points.size(); ++p) {
        const TimeTally& t = points[p][m];
        if (t.checked > 0)
          rows.push_back({sw.name, int(p), methods[m].name, t.checked, t.contacts, t.late,
                          t.early_median(), t.early_max()});
      }
  }
  return rows;
}

std::string toi_stability_csv(const std::vector<ToiStabilityRow>& rows) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to, "sweep,parameter,method,queries,contacts,late,early_median,early_max\n");
  for (const ToiStabilityRow& r : rows)
    fmt::format_to(to, "{},{},{},{},{},{},{:.6g},{:.6g}\n", r.sweep, r.parameter, r.method,
                   r.queries, r.contacts, r.late, r.early_median, r.early_max);
  return fmt::to_string(out);
}

const std::vector<StabilitySweep>& stability_sweeps() {
  static const std::vector<StabilitySweep> sweeps = [] {
    std::vector<StabilitySweep> out;
    for (const SweepDef& d : sweep_defs()) out.push_back(d.sweep);
    return out;
  }();
  return sweeps;
}

std::vector<StabilityRow> stability(long per_point, std::uint64_t seed,
                                    const ProgressSink& progress) {
  std::vector<Method> methods = all_methods();
  methods.erase(
      std::remove_if(methods.begin(), methods.end(), [](const Method& m) { return m.is_twin; }),
      methods.end());
  std::vector<StabilityRow> rows;
  long done = 0;
  for (const SweepDef& def : sweep_defs()) {
    const StabilitySweep& sw = def.sweep;
    report(progress, {"stability sweeps", done++, long(sweep_defs().size()), "sweeps"});
    const auto failure = sweep_rates(def, methods, per_point, seed);
    for (std::size_t m = 0; m < methods.size(); ++m)
      for (std::size_t p = 0; p < failure[m].size(); ++p)
        rows.push_back({sw.name, int(p), methods[m].name, failure[m][p]});
  }
  return rows;
}

std::string stability_csv(const std::vector<StabilityRow>& rows) {
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out), "sweep,parameter,method,failure_rate\n");
  for (const StabilityRow& r : rows)
    fmt::format_to(std::back_inserter(out), "{},{},{},{:.6g}\n", r.sweep, r.parameter, r.method,
                   r.failure_rate);
  return fmt::to_string(out);
}

}  // namespace fdh::verify

// `robust` within δ against its exact twin (exact::ccd_hit, ccd_toi and compare_with_toi at
// q.min_distance > 0): on the moving generator families' cases at δ of several sizes, and on
// close calls (δ = the least distance, or the distance at a drawn time, times 1 ± 2^-k), every
// certain answer of the filter is exact's (0 FP, 0 FN), and robust_ccd_toi's enclosure holds t*_δ
// (never late), no wider than asked.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <sstream>
#include <string>

#include "brute_distance.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/gen/rapidcheck.hpp"

namespace fdh {
namespace {

// "" if robust within δ keeps its promises on q, else what it broke.
std::string broken_delta_promise(const Query& q, double w) {
  const bool hit = exact::ccd_hit(q);
  const Filtered f = robust_ccd_filter(q);
  if (f != Filtered::Uncertain && (f == Filtered::Yes) != hit) return "filter verdict";
  const Toi toi = robust_ccd_toi(q, w, exact::ccd_toi);
  if (toi.hit != hit) return "TOI verdict";
  if (!hit) return toi.t_lo == 1 && toi.t_hi == 1 ? "" : "no contact but not [1, 1]";
  if (!(0 <= toi.t_lo && toi.t_lo <= toi.t_hi && toi.t_hi <= 1)) return "not in [0, 1]";
  if (toi.t_hi - toi.t_lo > w) return "too wide";
  const int lo = exact::compare_with_toi(q, toi.t_lo);
  if (lo > 0) return "late";
  if (exact::compare_with_toi(q, toi.t_hi) < 0) return "t_hi before t*_δ";
  if (toi.t_lo == 0 && lo != 0) return "0 where t*_δ > 0";
  return "";
}

std::string describe(const Query& q) {
  std::ostringstream out;
  out.precision(17);
  out << (q.kind == QueryKind::VertexFace ? "vf" : "ee") << " δ=" << q.min_distance;
  for (const Vec3& v : q.x) out << " (" << v.x << " " << v.y << " " << v.z << ")";
  return out.str();
}

// The largest |coordinate|: δ scaled to the case's size.
double size_of(const Query& q) {
  double m = 0;
  for (const Vec3& v : q.x) m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return m > 0 ? m : 1;
}

TEST(CcdRobustDeltaExact, MovingFamiliesAtSeveralDeltas) {
  int checked = 0, decided = 0;
  for (const verify::Family& fam : verify::all_families()) {
    if (!fam.moving) continue;
    for (std::uint64_t seed = 0; seed < 24; ++seed) {
      Query q = verify::generate(fam, seed).query;
      for (const double rel : {0x1p-40, 0x1p-20, 0x1p-10, 0.25}) {
        q.min_distance = rel * size_of(q);
        const std::string broken = broken_delta_promise(q, kDefaultToiWidth);
        EXPECT_EQ(broken, "") << fam.name << " seed " << seed << ": " << describe(q);
        ++checked, decided += robust_ccd_filter(q) != Filtered::Uncertain;
      }
    }
  }
  EXPECT_GT(checked, 0);
  // Most are decided by the filter alone (what the filter is for; the rest is exact's).
  EXPECT_GT(decided, checked / 2) << decided << " of " << checked;
}

TEST(CcdRobustDeltaExact, CloseCallsBothWays) {
  EXPECT_TRUE(rc::check("robust-within-delta-equals-exact", [] {
    Query q;
    q.kind = *rc::gen::element(QueryKind::VertexFace, QueryKind::EdgeEdge);
    const int grid = *rc::gen::element(1, 4, 1024);
    for (Vec3& v : q.x) {
      const auto c = [grid] { return double(*rc::gen::inRange(-grid, grid + 1)) / grid; };
      v = {c(), c(), c()};
    }
    // The least distance over the step, or the distance at a dyadic time (long double's brute
    // force), nudged by 2^-k either way: close calls, hits and misses.
    const long double d = *rc::gen::arbitrary<bool>()
                              ? brute::least_distance(q, 1)
                              : brute::distance_at(q, *rc::gen::inRange(0, 65) / 64.0);
    const int k = *rc::gen::inRange(8, 50);
    const double nudge = std::ldexp(1.0, -k);
    q.min_distance = double(d) * (*rc::gen::arbitrary<bool>() ? 1 + nudge : 1 - nudge);
    RC_PRE(q.min_distance > 0);
    const std::string broken = broken_delta_promise(q, kDefaultToiWidth);
    RC_LOG() << describe(q);
    RC_ASSERT(broken == "");
    const Filtered f = robust_ccd_filter(q);
    RC_TAG(exact::ccd_hit(q) ? "hit" : "miss",
           f == Filtered::Uncertain ? "left to exact" : "filter decided");
  }));
}

}  // namespace
}  // namespace fdh

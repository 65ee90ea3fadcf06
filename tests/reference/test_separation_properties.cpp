// The exact minimum-separation CCD against a second exact formulation: CGAL's exact squared
// distance on rationals at one time (exact::compare_distance_at), which shares nothing with the
// pieces of exact_separation.cpp. Points on a coarse dyadic grid, so that distances exactly δ,
// parallel and coplanar configurations and degenerate primitives are common. Also monotonicity
// in δ, and, on the CCD benchmark sample (skipped without one, FDH_CCD_SAMPLE), that a contact
// is within every δ > 0 no later.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../properties/test_name.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/distance.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::exact {
namespace {

// A coordinate on the grid of eighths in [-2, 2].
rc::Gen<double> grid() {
  return rc::gen::map(rc::gen::inRange(-16, 17), [](int i) { return i / 8.0; });
}

rc::Gen<Vec3> grid_point() {
  return rc::gen::apply(
      [](double x, double y, double z) {
        return Vec3{x, y, z};
      },
      grid(), grid(), grid());
}

// A query on the grid, still or moving, with δ in eighths (distances like 1/2 or 5/8 are exact).
rc::Gen<Query> grid_query(bool still) {
  return rc::gen::apply(
      [still](bool edge_edge, std::vector<Vec3> x, int eighths) {
        Query q;
        q.kind = edge_edge ? QueryKind::EdgeEdge : QueryKind::VertexFace;
        for (int i = 0; i < 8; ++i) q.x[i] = x[still ? i % 4 : i];
        q.min_distance = eighths / 8.0;
        return q;
      },
      rc::gen::arbitrary<bool>(), rc::gen::container<std::vector<Vec3>>(8, grid_point()),
      rc::gen::inRange(1, 17));
}

TEST(SeparationProperties, StillConfigurationsAgreeWithCgalsDistance) {
  EXPECT_TRUE(rc::check("separation-still-vs-cgal", [] {
    const Query q = *grid_query(true);
    const bool within = compare_distance_at(q, 0) <= 0;
    RC_ASSERT(ccd_hit(q) == within);
    if (within) RC_ASSERT(compare_with_toi(q, 0) == 0);
  }));
}

TEST(SeparationProperties, MovingConfigurationsAgreeWithCgalsDistanceAtSampledTimes) {
  EXPECT_TRUE(rc::check("separation-moving-vs-cgal", [] {
    const Query q = *grid_query(false);
    const bool hit = ccd_hit(q);
    const Toi toi = ccd_toi(q, 0, 1, 0x1p-30);
    RC_ASSERT(toi.hit == hit);
    for (int i = 0; i <= 64; ++i) {
      const double t = i / 64.0;
      const int d = compare_distance_at(q, t);
      if (d <= 0) RC_ASSERT(hit && compare_with_toi(q, t) >= 0);
      if (hit && t < toi.t_lo) RC_ASSERT(d > 0);  // before the enclosure: farther than δ
    }
    if (!hit) return;
    RC_ASSERT(toi.t_hi - toi.t_lo <= 0x1p-30);
    RC_ASSERT(compare_with_toi(q, toi.t_lo) <= 0);
    RC_ASSERT(compare_with_toi(q, toi.t_hi) >= 0);
    if (toi.t_lo > 0)
      RC_ASSERT(compare_distance_at(q, toi.t_lo) > 0 || compare_with_toi(q, toi.t_lo) == 0);
    if (toi.t_lo == toi.t_hi) RC_ASSERT(compare_distance_at(q, toi.t_lo) <= 0);
  }));
}

TEST(SeparationProperties, WithinDeltaIsMonotoneInDelta) {
  EXPECT_TRUE(rc::check("separation-monotone", [] {
    Query q = *grid_query(false);
    const int more = *rc::gen::inRange(1, 17);
    const bool hit = ccd_hit(q);
    const Toi toi = ccd_toi(q, 0, 1, 0x1p-30);
    Query wider = q;
    wider.min_distance += more / 8.0;
    if (!hit) return;
    RC_ASSERT(ccd_hit(wider));
    RC_ASSERT(compare_with_toi(wider, toi.t_hi) >= 0);  // t*_wider <= t*_δ <= t_hi
  }));
}

// A moving family's query (near-contact constructions, large and tiny coordinates) within
// δ = 2^-k of its largest coordinate: the enclosure against compare_with_toi and CGAL, and a
// contact within δ no later.
class SeparationFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(SeparationFamily, AgreesWithCgalAndContact) {
  const verify::Family& f = *verify::family_named(GetParam());
  EXPECT_TRUE(rc::check("separation-family/" + f.name, [&f] {
    Query q = (*verify::gen_family(f)).query;
    const Toi contact = ccd_toi(q, 0, 1, 0x1p-30);
    double scale = 0;
    for (const Vec3& p : q.x)
      scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    RC_PRE(scale > 0);
    q.min_distance = std::ldexp(scale, -*rc::gen::element(10, 20, 40));
    const Toi toi = ccd_toi(q, 0, 1, 0x1p-30);
    RC_ASSERT(toi.hit == ccd_hit(q));
    if (contact.hit) RC_ASSERT(toi.hit && compare_with_toi(q, contact.t_hi) >= 0);
    for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0})
      if (compare_distance_at(q, t) <= 0) RC_ASSERT(toi.hit && compare_with_toi(q, t) >= 0);
    if (!toi.hit) return;
    RC_ASSERT(toi.t_hi - toi.t_lo <= 0x1p-30);
    RC_ASSERT(compare_with_toi(q, toi.t_lo) <= 0 && compare_with_toi(q, toi.t_hi) >= 0);
    if (compare_with_toi(q, toi.t_lo) < 0) RC_ASSERT(compare_distance_at(q, toi.t_lo) > 0);
  }));
}

INSTANTIATE_TEST_SUITE_P(All, SeparationFamily, ::testing::ValuesIn(verify::family_names(true)),
                         [](const auto& info) { return test_name(info.param); });

TEST(SeparationProperties, ASampleContactIsWithinEveryDeltaNoLater) {
  namespace fs = std::filesystem;
  const fs::path root = FDH_CCD_SAMPLE;  // the build's FDH_CCD_SAMPLE, empty for none
  if (!fs::is_directory(root)) GTEST_SKIP() << "no CCD benchmark sample (FDH_CCD_SAMPLE)";
  std::size_t checked = 0, contacts = 0;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (e.path().extension() != ".csv") continue;
    for (const verify::QueryRecord& r : verify::read_query_file(e.path().string())) {
      SCOPED_TRACE(r.file + ":" + std::to_string(r.line));
      Query q = r.query;
      const Toi contact = ccd_toi(q, 0, 1, 0x1p-30);
      q.min_distance = 0x1p-40;
      const Toi near = ccd_toi(q, 0, 1, 0x1p-30);
      EXPECT_EQ(ccd_hit(q), near.hit);
      if (contact.hit) {
        ++contacts;
        ASSERT_TRUE(near.hit);
        EXPECT_GE(compare_with_toi(q, contact.t_hi), 0);  // t*_δ <= t*_0 <= t_hi
      } else if (!near.hit) {
        EXPECT_GT(compare_distance_at(q, 0), 0);
        EXPECT_GT(compare_distance_at(q, 1), 0);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 2800u);
  EXPECT_GT(contacts, 0u);
}

}  // namespace
}  // namespace fdh::exact

// Peers certified side by side (fdh/peer_certify/peer_certify.hpp): on the same cases the project's
// own k-DOPs show 0 violations and the peers' known failures are found, shrunk and saved.
#include "fdh/peer_certify/peer_certify.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/io/peer_case_file.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

const PeerRow& row(const PeersReport& r, const std::string& library, const std::string& method) {
  for (const PeerRow& row : r.rows)
    if (row.library == library && row.method == method) return row;
  throw std::invalid_argument("no row " + library + " " + method);
}

TEST(Peers, OwnRowsHoldAndPeersFailOnTheSameCases) {
  PeerOptions o;
  o.quick = true;
  o.save_dir = fresh_temp_dir("peers").string();
  const PeersReport r = certify_peers(o);
  EXPECT_EQ(r.own_violations(), 0);
  EXPECT_TRUE(r.first_own_violation.empty());
  for (const PeerRow& own : r.rows)
    if (own.library == "fdhcert") {
      EXPECT_EQ(own.promise, Promise::Conservative);
      EXPECT_EQ(own.containment.checked, 300);
      EXPECT_EQ(own.containment.violations + own.overlap.violations, 0) << own.method;
    }
  // FCL's sums round on most full-precision sets; its 16-DOP never misses an overlap (each of
  // its projections rounds once, monotonically).
  const PeerRow& k16 = row(r, "fcl", "kdop16");
  EXPECT_GT(k16.containment.violations, 150);
  EXPECT_EQ(k16.overlap.violations, 0);
  EXPECT_GT(row(r, "fcl", "kdop24").overlap.violations, 0);
  EXPECT_GT(row(r, "bullet", "convex-hull-aabb").overlap.violations, 0);
  EXPECT_EQ(row(r, "bullet", "dbvt-from-points").containment.violations, 0);
  // The first violation of each failing (method, property) is saved, shrunk, and reads back.
  const PeerRow& hull = row(r, "bullet", "convex-hull-aabb");
  ASSERT_EQ(hull.overlap.shrunk.size(), 1u);
  const PeerCase c = read_peer_case(hull.overlap.shrunk.front());
  EXPECT_EQ(c.method, "convex-hull-aabb");
  EXPECT_LE(c.a.size() + c.b.size(), 3u);
  const nlohmann::ordered_json j = peers_json(r);
  EXPECT_EQ(j["rows"].size(), r.rows.size());
  EXPECT_NE(peers_markdown(r).find("| fcl | 0.7.0 (double) | `kdop24` | 24 | overlap |"),
            std::string::npos);
}

}  // namespace
}  // namespace fdh::verify

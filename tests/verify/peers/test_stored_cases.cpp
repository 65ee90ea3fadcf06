// The shrunk peer cases under corpus/peers/ (made by `fdhcert peers`): each one still makes its
// peer fail its property through the checker, and none makes the project's own k-DOPs fail.
#include <gtest/gtest.h>

#include <set>

#include "fdh/check/checker.hpp"
#include "fdh/io/peer_case_file.hpp"
#include "test_data.hpp"
#include "verify/peers/peer_methods.hpp"

namespace fdh::verify {
namespace {

const std::string kStored = FDH_SOURCE_DIR "/corpus/peers";

bool fails(const BoxMethod& m, const PeerCase& c) {
  if (c.property == "containment") return check_box(m, c.a.data(), c.a.size()) >= 0;
  const Verdicts v = check_overlap(m, c.a, c.b);
  return v.twin && !v.said;
}

TEST(StoredPeerCases, StillFailTheirPeerAndNotTheOwnKdops) {
  const std::vector<std::string> files = list_peer_case_files(kStored);
  ASSERT_FALSE(files.empty());
  for (const std::string& f : files) {
    const PeerCase c = read_peer_case(f);
    EXPECT_TRUE(fails(peer_method(c.library, c.method), c)) << f;
    for (const BoxMethod& own : all_box_methods()) EXPECT_FALSE(fails(own, c)) << f << " " << own.k;
  }
}

// The failures the peers are known for, each kept as at least one stored case: FCL's k-DOPs
// miss the exact extent, its 24-DOP calls touching sets disjoint, and Bullet's shapes' boxes
// (centre and extent) do both.
TEST(StoredPeerCases, KeepEveryKnownFailure) {
  std::set<std::string> kept;
  for (const std::string& f : list_peer_case_files(kStored)) {
    const PeerCase c = read_peer_case(f);
    kept.insert(c.library + " " + c.method + " " + c.property);
  }
  for (const char* known :
       {"fcl kdop16 containment", "fcl kdop18 containment", "fcl kdop24 containment",
        "fcl kdop24 overlap", "bullet convex-hull-aabb containment",
        "bullet convex-hull-aabb overlap", "bullet bvh-trimesh-aabb containment",
        "bullet bvh-trimesh-aabb overlap"})
    EXPECT_EQ(kept.count(known), 1u) << known;
}

}  // namespace
}  // namespace fdh::verify

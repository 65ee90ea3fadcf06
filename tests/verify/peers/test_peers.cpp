// The peer libraries (verify/peers/src/libraries.def): each in double precision, with its
// version from its headers, its box methods carrying one integer direction per slab.
#include "fdh/peers/peers.hpp"

#include <gtest/gtest.h>

namespace fdh::verify {
namespace {

TEST(PeerLibraries, DoubleWithTheirVersionsAndOwnDirections) {
  struct Expected {
    const char* name;
    const char* version;
    std::vector<int> ks;
  };
  const std::vector<Expected> expected = {{"fcl", "0.7.0", {16, 18, 24}},
                                          {"bullet", "3.24", {6, 6, 6}}};
  const std::vector<PeerLibrary> libs = all_peer_libraries();
  ASSERT_EQ(libs.size(), expected.size());
  for (std::size_t i = 0; i < libs.size(); ++i) {
    EXPECT_EQ(libs[i].name, expected[i].name);
    EXPECT_EQ(libs[i].version, expected[i].version);
    EXPECT_EQ(libs[i].precision, "double");
    std::vector<int> ks;
    for (const BoxMethod& m : libs[i].methods) {
      ks.push_back(m.k);
      EXPECT_EQ(m.directions.size() * 2, std::size_t(m.k)) << m.name;
      EXPECT_EQ(m.promise, Promise::None) << m.name;
    }
    EXPECT_EQ(ks, expected[i].ks) << libs[i].name;
  }
}

}  // namespace
}  // namespace fdh::verify

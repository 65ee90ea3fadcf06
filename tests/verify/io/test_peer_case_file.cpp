// Peer case files (fdh/io/peer_case_file.hpp): written and read back bit for bit; bad ones
// refused with FILE:LINE.
#include "fdh/io/peer_case_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fdh/io/input_error.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

std::string written(const std::filesystem::path& dir, const std::string& text) {
  const std::string path = (dir / "case.txt").string();
  std::ofstream(path) << text;
  return path;
}

TEST(PeerCaseFile, RoundTripsEveryBit) {
  const auto dir = fresh_temp_dir("peer_case");
  const PeerCase c{
      "fcl", "kdop24", "overlap", {{0.1, -0x1.fffffffffffffp+3, 0}}, {{1e-300, 3, -0.0}}};
  const PeerCase back = read_peer_case(written(dir, peer_case_text(c, {"a comment"})));
  EXPECT_EQ(back.library, "fcl");
  EXPECT_EQ(back.method, "kdop24");
  EXPECT_EQ(back.property, "overlap");
  EXPECT_EQ(back.a, c.a);
  EXPECT_EQ(back.b, c.b);
  EXPECT_EQ(peer_case_hash(back), peer_case_hash(c));
  EXPECT_EQ(peer_case_file_name(c), "kdop24-overlap-" + peer_case_hash(c) + ".txt");
}

TEST(PeerCaseFile, RefusesBadCasesNamingTheLine) {
  const auto dir = fresh_temp_dir("peer_case");
  const auto error = [&](const std::string& text) {
    try {
      read_peer_case(written(dir, text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("peer fcl kdop24 inside\n").find("case.txt:1: expected `peer"),
            std::string::npos);
  EXPECT_NE(error("peer fcl kdop24 containment\na 1 2\n").find("case.txt:2: a point"),
            std::string::npos);
  EXPECT_NE(error("peer fcl kdop24 containment\na 1 2 nan\n").find("case.txt:2:"),
            std::string::npos);
  EXPECT_NE(error("peer fcl kdop24 overlap\na 1 2 3\n").find("needs points in set b"),
            std::string::npos);
  EXPECT_NE(error("# only a comment\n").find("no `peer` line"), std::string::npos);
}

}  // namespace
}  // namespace fdh::verify

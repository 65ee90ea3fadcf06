// fdhcert audit --part I/N and --merge, run in-process: the parts of a sequence with a planted
// crossing, merged, give the whole run's certificate (the same JSON but for the costs, the same
// case files and picture) for any number of parts and any --keep; parts that do not belong
// together are refused (exit 2, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The sphere scene's first 24 frames with cloth vertex 312 pushed into the sphere at frame 12:
// violations in the steps 11 -> 12 and 12 -> 13 and in frame 12, the frame that parts 1/2 and
// 2/2 share.
fs::path planted(const fs::path& root) {
  const fs::path dir = root / "frames";
  const CliRun s = fdhcert({"simulate", std::string(FDH_SOURCE_DIR) + "/corpus/scenes/sphere.scene",
                            "--frames", "24", "--obj", dir.string(), "--no-check"});
  EXPECT_EQ(s.status, 0) << s.err;
  const fs::path frame = dir / "frame_00012.obj";
  std::string text = bytes_of(frame);
  std::size_t at = 0;
  for (int line = 1; line < 314; ++line) at = text.find('\n', at) + 1;  // cloth vertex 312
  text.replace(at, text.find('\n', at) - at, "v 0.013 0.5 0.021");      // inside the sphere
  std::ofstream(frame, std::ios::binary) << text;
  return dir;
}

std::string fmt_part(const std::string& keep, int i, int n) {
  return "part-keep" + keep + "-" + std::to_string(i) + "of" + std::to_string(n);
}

Json without_cost(Json j) {
  j.erase("cost");
  return j;
}

// Every file of `dir` but the certificate's two (their costs differ), by name and content.
std::map<std::string, std::string> outputs(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (e.is_regular_file() && name != "audit.json" && name != "audit.md")
      files[name] = bytes_of(e.path());
  }
  return files;
}

TEST(AuditParts, MergedPartsGiveTheWholeRunsCertificate) {
  const fs::path root = fresh_temp_dir("audit_parts");
  const fs::path frames = planted(root);
  for (const std::string keep : {"2", "16"}) {
    const fs::path whole = root / ("whole-" + keep);
    const CliRun w = fdhcert({"audit", frames.string(), "--keep", keep, "--out", whole.string()});
    ASSERT_EQ(w.status, 1) << w.err;
    const Json expected = Json::parse(bytes_of(whole / "audit.json"));
    ASSERT_GT(expected["violations"].get<long>(), 0);
    for (const int n : {1, 2, 3, 24}) {
      std::vector<std::string> merge = {"audit", "--merge"};
      for (int i = n; i >= 1; --i) {  // given in any order
        const fs::path part = root / fmt_part(keep, i, n);
        const CliRun p =
            fdhcert({"audit", frames.string(), "--keep", keep, "--part",
                     std::to_string(i) + "/" + std::to_string(n), "--out", part.string()});
        ASSERT_LE(p.status, 1) << p.err;
        const Json pj = Json::parse(bytes_of(part / "audit.json"));
        EXPECT_EQ(pj["part"]["index"], i);
        EXPECT_EQ(pj["part"]["first_frame"], (i - 1) * 24 / n);
        EXPECT_EQ(pj["part"]["last_frame"], i * 24 / n);
        merge.push_back(part.string());
      }
      const fs::path out = root / ("merged-" + keep + "-" + std::to_string(n));
      merge.insert(merge.end(), {"--out", out.string(), "--json"});
      const CliRun m = fdhcert(merge);
      ASSERT_EQ(m.status, 1) << m.err;
      const Json got = Json::parse(m.out);
      EXPECT_EQ(without_cost(got), without_cost(expected)) << n << " parts, --keep " << keep;
      EXPECT_EQ(got, Json::parse(bytes_of(out / "audit.json")));
      EXPECT_EQ(outputs(out), outputs(whole)) << n << " parts: the picture and case files";
      EXPECT_TRUE(fs::exists(out / "first-violation.png"));
    }
  }
}

// Parts that are not every part of one run, once each: exit 2, the part's file named, nothing
// written. And --part past the sequence's steps, or without --out.
TEST(AuditParts, PartsThatDoNotBelongTogetherAreRefused) {
  const fs::path root = fresh_temp_dir("audit_parts_bad");
  const fs::path frames = planted(root);
  const auto part = [&](const std::string& i_of_n, const std::string& name,
                        std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"audit", frames.string(), "--part",
                                     i_of_n,  "--out",         (root / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_LE(fdhcert(args).status, 1) << name;
    return (root / name).string();
  };
  const std::string a1 = part("1/2", "a1"), a2 = part("2/2", "a2"), b2 = part("2/3", "b2"),
                    k2 = part("2/2", "k2", {"--keep", "3"});
  const fs::path whole = root / "whole";
  EXPECT_EQ(fdhcert({"audit", frames.string(), "--out", whole.string()}).status, 1);
  const std::string out = (root / "out").string();
  struct Case {
    std::vector<std::string> dirs;
    std::string error;
  };
  const std::vector<Case> cases = {
      {{a2}, a2 + "/audit.json: part 2/2, and no part 1/2 is given"},
      {{a1}, a1 + "/audit.json: the last part given is 1/2"},
      {{a1, b2}, b2 + "/audit.json: part 2/3 cannot follow part 1/2"},
      {{a1, a2, a2}, a2 + "/audit.json: part 2/2 cannot follow part 2/2"},
      {{a1, k2}, k2 + "/audit.json: --keep 3, and part 1 has 16"},
      {{a1, whole.string()}, whole.string() + "/audit.json: not a part's certificate"},
      {{a1, (root / "none").string()}, (root / "none").string() + "/audit.json: no such file"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"audit", "--merge"};
    args.insert(args.end(), c.dirs.begin(), c.dirs.end());
    args.insert(args.end(), {"--out", out});
    const CliRun r = fdhcert(args);
    EXPECT_EQ(r.status, 2) << c.error;
    EXPECT_NE(r.err.find("fdhcert: error: " + c.error), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.error;
  }
  EXPECT_EQ(fdhcert({"audit", "--merge", a1, a2}).status, 2);  // no --out
  const CliRun past = fdhcert({"audit", frames.string(), "--part", "1/25", "--out", out});
  EXPECT_EQ(past.status, 2);
  EXPECT_NE(past.err.find("the sequence has 24 steps"), std::string::npos) << past.err;
  EXPECT_EQ(fdhcert({"audit", frames.string(), "--part", "1/2"}).status, 2);  // no --out
  EXPECT_EQ(fdhcert({"audit", frames.string(), "--part", "3/2", "--out", out}).status, 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace fdh::verify

// Promises judged under the metamorphic transforms (check/metamorphic.hpp): a plug-in that is
// conservative near the unit scale only is caught by certify and fuzz --metamorphic through the
// scales alone, with no truth file; an honest conservative plug-in passes the same stage.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli_run.hpp"
#include "fdh/certify/certify_metamorphic.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/io/query_io.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// certify with its quickest options: no corpus, no scenes, no soups, no peers, and either
// `per_family` queries of every family or none and `extra`.
CliRun quick_certify(const std::string& plugin, const fs::path& out, const std::string& per_family,
                     const std::vector<std::string>& extra = {}) {
  const fs::path corpus = fresh_temp_dir("transforms_corpus");  // empty
  std::vector<std::string> args = {
      "certify",    "--quick",      "--plugin", plugin,    "--corpus", corpus.string(), "--out",
      out.string(), "--per-family", per_family, "--soups", "0",        "--peer-cases",  "0"};
  args.insert(args.end(), extra.begin(), extra.end());
  return fdhcert(args);
}

// Three small queries that all touch, with no truth: static and moving vertex-face, edge-edge.
fs::path small_hits() {
  const fs::path file = fresh_temp_dir("transforms_hits") / "hits.vf";
  std::ofstream(file)
      << "vf static 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0\n"
         "vf rising 0.25 0.25 0  0 0 -1  1 0 -1  0 1 -1  0.25 0.25 0  0 0 1  1 0 1  0 1 1\n"
         "ee falling -1 0 1  1 0 1  0 -1 0  0 1 0  -1 0 -1  1 0 -1  0 -1 0  0 1 0\n";
  return file;
}

// The certificate's rows of one method.
nlohmann::json rows_of(const nlohmann::json& rows, const std::string& method) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows)
    if (r["method"] == method) out.push_back(r);
  return out;
}

TEST(CertifyTransforms, CatchesAPlugInThatMissesHitsBeyond2To33ThroughTheScalesAlone) {
  // Not the generator families: far-from-origin reaches 2^42 and catches it without a transform.
  const fs::path out = fresh_temp_dir("transforms_far_miss");
  const CliRun r = quick_certify(FDH_FAR_MISS_PLUGIN, out, "0", {small_hits().string()});
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  // Named with the transform that shows it, and the query it was drawn as.
  EXPECT_TRUE(has(r.err,
                  "far-miss says no, the exact twin says hit: misses a hit (breaks CONSERVATIVE) "
                  "on the query after scale-2^"))
      << r.err;
  EXPECT_TRUE(has(r.err, "(metamorphic, ")) << r.err;
  EXPECT_TRUE(has(r.err, "(query static from ")) << r.err;  // the first query, as drawn
  // The transformed query is saved, with the exact truth, and replays as a broken promise.
  std::size_t saved = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    if (e.path().filename().string().rfind("violation-", 0) != 0) continue;
    ++saved;
    EXPECT_TRUE(has(text_of(e.path()), "after scale-2^")) << e.path();
    // The query as drawn, before the transform, in a comment.
    EXPECT_TRUE(has(text_of(e.path()), "\n# before scale-2^40: vf static 0x1p-2 0x1p-2 0x1p+0"))
        << text_of(e.path());
    EXPECT_TRUE(has(r.err, e.path().string())) << r.err;
    const QueryRecord q = read_native(e.path().string()).at(0);
    EXPECT_EQ(q.truth, Truth::Yes);
    const CliRun replay = fdhcert({"classify", e.path().string(), "--plugin", FDH_FAR_MISS_PLUGIN,
                                   "--methods", "far-miss", "--check"});
    EXPECT_EQ(replay.status, 1) << replay.out << replay.err;
  }
  EXPECT_EQ(saved, 1u);
  // Every query certify was given keeps the promise: only the transforms found the misses.
  const nlohmann::json c = nlohmann::json::parse(text_of(out / "certificate.json"));
  EXPECT_FALSE(c["certified"].get<bool>());
  const nlohmann::json promises = rows_of(c["promises"], "far-miss");
  ASSERT_EQ(promises.size(), 3u);
  for (const auto& p : promises) {
    EXPECT_GT(p["checked"], 0) << p;
    EXPECT_EQ(p["violations"], 0) << p;
  }
  const nlohmann::json meta = rows_of(c["metamorphic"], "far-miss").at(0);
  EXPECT_GT(meta["promise_broken"], 0) << meta;
  EXPECT_GT(meta["judged"], meta["promise_broken"]) << meta;
  EXPECT_TRUE(has(r.out, "promises under transforms (broken / judged): robust 0/")) << r.out;
}

TEST(CertifyTransforms, AnHonestConservativePlugInPassesTheStage) {
  const fs::path out = fresh_temp_dir("transforms_aabb");
  const CliRun r = quick_certify(FDH_EXAMPLE_PLUGIN, out, "2", {small_hits().string()});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const nlohmann::json c = nlohmann::json::parse(text_of(out / "certificate.json"));
  const nlohmann::json meta = rows_of(c["metamorphic"], "aabb").at(0);
  EXPECT_EQ(meta["promise"], "conservative");
  EXPECT_GT(meta["judged"], 1000) << meta;
  EXPECT_EQ(meta["promise_broken"], 0) << meta;
  // Every scale and translation of the ladder is in the certificate, applied or skipped.
  std::set<std::string> seen;
  long skipped = 0;
  for (const auto& t : c["metamorphic_transforms"]) {
    seen.insert(t["transform"].get<std::string>());
    skipped += t["skipped"].get<long>();
  }
  for (const char* t : {"scale-2^-60", "scale-2^60", "translate-2^-60", "translate-2^60"})
    EXPECT_EQ(seen.count(t), 1u) << t;
  EXPECT_GT(skipped, 0);
  EXPECT_TRUE(has(text_of(out / "certificate.md"), "| `scale-2^60` |"));
}

TEST(CertifyTransforms, FuzzMetamorphicFindsTheBrokenPromiseAndStoresIt) {
  const fs::path out = fresh_temp_dir("transforms_fuzz");
  const CliRun r = fdhcert({"fuzz", "--metamorphic", "--plugin", FDH_FAR_MISS_PLUGIN, "--method",
                            "far-miss", "--family", "through-edge", "--count", "20", "--threads",
                            "1", "--out", out.string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(r.out);
  long broken = 0;
  for (const auto& f : s["files"]) {
    const std::string text = text_of(f.get<std::string>());
    if (!has(text, "(breaks CONSERVATIVE)")) continue;  // a false alarm that comes and goes
    ++broken;
    EXPECT_TRUE(has(text,
                    "far-miss says no, the exact twin says hit: misses a hit (breaks "
                    "CONSERVATIVE) on the query after "))
        << text;
    EXPECT_EQ(read_native(f.get<std::string>()).at(0).truth, Truth::Yes);
  }
  EXPECT_GT(broken, 0) << r.out;
}

// A method that promises CONSERVATIVE and says "no" beyond a scale: the first transform that
// breaks it is judged against the twin's verdict, which the scale keeps; a verdict change of a
// conservative method that stays on the safe side is only counted.
TEST(CertifyTransforms, TheCertifierJudgesAPromiseUnderTheTransforms) {
  Method near;
  near.name = "near";
  near.promise = Promise::Conservative;
  near.test[std::size_t(Decision::PointTriangle)] = [](const Query& q) {
    return std::fabs(q.x[1].x) + std::fabs(q.x[2].x) < 0x1p33;  // hit near the origin
  };
  const MetamorphicCertifier cert({near});
  std::vector<MetamorphicCheck> rows = cert.rows();
  std::vector<TransformCount> counts = transform_counts();
  Query q;  // the segment (1/4, 1/4, 1) to (1/4, 1/4, -1) through the unit triangle: a hit
  q.x = {Vec3{0.25, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         Vec3{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  ASSERT_TRUE(twin_hit(q));
  const auto broken = cert.check(q, true, rows, counts);
  ASSERT_TRUE(broken);
  EXPECT_EQ(broken->what,
            "near says no, the exact twin says hit: misses a hit (breaks CONSERVATIVE) on the "
            "query after scale-2^40 (metamorphic, point-triangle)");
  EXPECT_EQ(broken->saved.x[0].x, 0x1p38);  // the transformed query
  EXPECT_EQ(broken->transform, "scale-2^40");
  EXPECT_EQ(rows[0].broken, 3);  // scale-2^40, scale-2^60 and translate-2^40
  EXPECT_EQ(rows[0].judged, rows[0].checked);
  // A hit where the twin says no keeps the promise: judged, not broken.
  std::vector<MetamorphicCheck> none = cert.rows();
  q.x[0].x = q.x[4].x = 2;  // the segment misses the triangle
  ASSERT_FALSE(twin_hit(q));
  EXPECT_FALSE(cert.check(q, false, none, counts));
  EXPECT_GT(none[0].judged, 0);
  EXPECT_EQ(none[0].broken, 0);
}

// Each transform applies where it is exact and leaves the normal range nowhere; skipped ones are
// counted, a relabelling for the other kind is neither.
TEST(CertifyTransforms, TransformsAreCountedAppliedOrSkipped) {
  Query q;
  q.x = {Vec3{0.375, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         Vec3{0.375, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<TransformCount> counts = transform_counts();
  const std::vector<Transformed> moved = transforms_of(q, &counts);
  long applied = 0, skipped = 0;
  for (const TransformCount& t : counts) {
    applied += t.applied, skipped += t.skipped;
    if (t.transform == "translate-2^60" || t.transform == "translate-2^-60") {
      EXPECT_EQ(t.skipped, 1) << t.transform;  // 2^60 + 3/8 would round
    }
    if (t.transform == "scale-2^60" || t.transform == "translate-2^40") {
      EXPECT_EQ(t.applied, 1) << t.transform;
    }
    if (t.transform == "edges-swap") {
      EXPECT_EQ(t.applied + t.skipped, 0);
    }
  }
  EXPECT_EQ(applied, long(moved.size()));
  EXPECT_GT(skipped, 0);
  Query tiny = q;
  for (Vec3& v : tiny.x) v = {std::ldexp(v.x, -980), std::ldexp(v.y, -980), std::ldexp(v.z, -980)};
  std::vector<TransformCount> tiny_counts = transform_counts();
  transforms_of(tiny, &tiny_counts);
  for (const TransformCount& t : tiny_counts)
    if (t.transform == "scale-2^-60") {
      EXPECT_EQ(t.skipped, 1);  // 3 x 2^-1043: below the normal range
    }
}

}  // namespace
}  // namespace fdh::verify

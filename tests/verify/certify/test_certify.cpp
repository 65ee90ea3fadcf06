#include "fdh/certify/certify.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <filesystem>
#include <fstream>

#include "fdh/certify/certify_metamorphic.hpp"
#include "fdh/cli/cli.hpp"
#include "fdh/os/build_info.hpp"

#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

CertifyOptions small(const fs::path& corpus, const fs::path& out) {
  CertifyOptions o;
  o.corpus_dir = corpus.string();
  o.out_dir = out.string();
  o.per_family = 20;
  o.soups = 3;
  o.scene_frames = 500;
  o.scene_stride = 100;
  o.peer_cases = 60;
  return o;
}

// Queries checked, or promises broken, over every method's moving decisions.
long moving(const Certificate& c, long PromiseCheck::*count) {
  long n = 0;
  for (const PromiseCheck& p : c.promises)
    if (p.decision != Decision::PointTriangle) n += p.*count;
  return n;
}

TEST(Certify, CertifiesTheCommittedCorpusAndCountsEveryCheck) {
  const fs::path out = fresh_temp_dir("certify_ok");
  const Certificate c = certify(small(FDH_SOURCE_DIR "/corpus", out));
  EXPECT_TRUE(c.certified()) << c.first_violation;
  EXPECT_GT(c.corpus_queries, 50);
  EXPECT_EQ(c.fuzzed_queries, 20 * long(c.families.size() + c.moving_families.size()));
  EXPECT_EQ(c.moving_families.size(), 9u);
  EXPECT_GT(moving(c, &PromiseCheck::checked), 20 * 9 - 1);
  EXPECT_GE(c.scenes, 7);
  EXPECT_GT(c.scene_queries, 0);
  EXPECT_EQ(c.boxes[0].soup_pairs, 3);
  EXPECT_GT(c.boxes[3].boxes, c.corpus_queries);
  EXPECT_GT(c.truths, 50);
  // Every method of the registry under the metamorphic transforms; promised ones change nothing.
  ASSERT_EQ(c.metamorphic.size(), all_methods().size());
  for (const MetamorphicCheck& m : c.metamorphic) {
    EXPECT_GT(m.checked, 1000) << m.method;
    if (m.promise != Promise::None) {
      EXPECT_EQ(m.violations, 0) << m.method;
    }
  }
  const std::string json = certificate_json(c);
  EXPECT_NE(json.find("\"metamorphic\""), std::string::npos);
  EXPECT_NE(certificate_markdown(c).find("## Metamorphic checks"), std::string::npos);
  EXPECT_NE(json.find("\"certified\": true"), std::string::npos);
  EXPECT_NE(json.find("\"cgal\": \"5."), std::string::npos);
  EXPECT_NE(json.find("\"promises\""), std::string::npos);
  EXPECT_NE(certificate_markdown(c).find("**Certified**"), std::string::npos);
  // The peers beside the own k-DOPs: the own rows hold, the peers' versions are recorded.
  EXPECT_EQ(c.peers.own_violations(), 0);
  EXPECT_EQ(c.peers.rows.front().containment.checked, 60);
  EXPECT_GT(c.peers.rows.front().containment.stored, 0);  // corpus/peers replayed
  EXPECT_NE(json.find("\"version\": \"0.7.0\""), std::string::npos);
  EXPECT_NE(json.find("\"version\": \"3.24\""), std::string::npos);
  EXPECT_NE(certificate_markdown(c).find("## Peers"), std::string::npos);
}

// A method with a promise whose verdict changes under a transform breaks it; one without a
// promise is only counted.
TEST(Certify, AMetamorphicChangeBreaksOnlyAPromise) {
  Method sided;  // "hit" iff the point starts at x > 0: a mirror or an axis swap changes that
  sided.name = "sided";
  sided.test[std::size_t(Decision::PointTriangle)] = [](const Query& q) { return q.x[0].x > 0; };
  Method promised = sided;
  promised.name = "promised";
  promised.promise = Promise::Exact;
  const MetamorphicCertifier cert({sided, promised});
  std::vector<MetamorphicCheck> rows = cert.rows();
  ASSERT_EQ(rows.size(), 2u);
  Query q;
  q.x = {Vec3{1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         Vec3{1, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto broken = cert.check(q, twin_hit(q), rows);
  ASSERT_TRUE(broken);
  // The promised method's answer after the axis swap breaks its promise (the twin, which the
  // transform keeps, says hit): judged first, the transformed query saved.
  EXPECT_EQ(broken->what.rfind("promised says no, the exact twin says hit: misses a hit (breaks "
                               "EXACT) on the query after axes-",
                               0),
            0u)
      << broken->what;
  EXPECT_NE(broken->saved.x, q.x);
  EXPECT_GT(rows[0].violations, 0);
  EXPECT_EQ(rows[0].violations, rows[1].violations);
  EXPECT_GT(rows[0].checked, rows[0].violations);
  EXPECT_EQ(rows[0].judged, 0);  // no promise: counted only
  EXPECT_EQ(rows[1].judged, rows[1].checked);
  EXPECT_EQ(rows[1].broken, rows[1].violations);  // every change is away from the twin's hit
  Certificate c;
  c.metamorphic = rows;
  EXPECT_EQ(c.violations(), rows[1].violations + rows[1].broken);  // the promised row only
}

TEST(Certify, AWrongStoredTruthIsAViolationSavedAsACorpusFile) {
  const fs::path corpus = fresh_temp_dir("certify_bad_corpus"),
                 out = fresh_temp_dir("certify_bad_out");
  std::ofstream(corpus / "wrong.vf")
      << "vf wrong 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  0\n";
  std::ostringstream so, se;
  const int status = run_cli({"certify", "--corpus", corpus.string(), "--out", out.string(),
                              "--per-family", "5", "--soups", "1", "--peer-cases", "20"},
                             so, se);
  EXPECT_EQ(status, 1);
  EXPECT_NE(se.str().find("wrong.vf:1"), std::string::npos) << se.str();
  EXPECT_NE(so.str().find("\nmetamorphic (verdicts changed / transformed queries): exact 0/"),
            std::string::npos)
      << so.str();
  int saved = 0;
  for (const auto& e : fs::directory_iterator(out))
    saved += e.path().filename().string().rfind("violation-", 0) == 0;
  EXPECT_EQ(saved, 1);
  EXPECT_TRUE(fs::exists(out / "certificate.json"));
}

// A moving query goes through CCD: a wrong stored truth there is a violation too.
TEST(Certify, AWrongTruthOnAMovingQueryIsAViolation) {
  const fs::path corpus = fresh_temp_dir("certify_moving_corpus"),
                 out = fresh_temp_dir("certify_moving_out");
  // The triangle rises through the still point at t = 1/2: a hit, stored as 0.
  std::ofstream(corpus / "rising.vf") << "vf rising  0.25 0.25 0  0 0 -1  1 0 -1  0 1 -1  "
                                         "0.25 0.25 0  0 0 1  1 0 1  0 1 1  0\n";
  CertifyOptions o = small(corpus, out);
  o.per_family = 2;
  const Certificate c = certify(o);
  EXPECT_FALSE(c.certified());
  EXPECT_EQ(c.truth_violations, 1);
  EXPECT_EQ(moving(c, &PromiseCheck::violations), 0);
  EXPECT_NE(c.first_violation.find("rising.vf:1"), std::string::npos) << c.first_violation;
}

// The certificate does not depend on the thread count: the same JSON and text with 1, 2 and 64
// threads (more than the work items of some stages), and the same first violation where
// several queries violate in different chunks, whichever chunk finishes first.
TEST(Certify, TheSameCertificateForAnyThreadCount) {
  const fs::path corpus = fresh_temp_dir("certify_threads_corpus");
  fs::create_directories(corpus / "scenes");
  for (const char* name : {"a.scene", "b.scene"})  // two scenes: each runs on a core of its own
    fs::copy(FDH_SOURCE_DIR "/corpus/scenes/table-rest.scene", corpus / "scenes" / name);
  std::ofstream many(corpus / "many.vf");
  for (int i = 1; i <= 40; ++i)  // the segment through the triangle: a hit, stored as 0 thrice
    many << "vf q" << i << " " << 0.125 + i / 128.0
         << " 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  "
         << (i == 20 || i == 30 || i == 38 ? 0 : 1) << "\n";
  many.close();
  std::string json, markdown;
  const fs::path out = fresh_temp_dir("certify_threads_out") / "out";  // one path: it is printed
  for (const std::size_t threads : {1, 2, 64}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    fs::remove_all(out);
    fs::create_directories(out);
    CertifyOptions o = small(corpus, out);
    o.scene_frames = 5;  // the cloth rests on the table from the start: queries every frame
    o.scene_stride = 5;
    const Certificate c = certify(o);
    EXPECT_EQ(c.truth_violations, 3);
    EXPECT_NE(c.first_violation.find("many.vf:20)"), std::string::npos) << c.first_violation;
    EXPECT_GT(c.scene_queries, 0);
    if (threads == 1) json = certificate_json(c), markdown = certificate_markdown(c);
    EXPECT_EQ(certificate_json(c), json) << threads;
    EXPECT_EQ(certificate_markdown(c), markdown) << threads;
  }
}

// The certificate names the commit the binary was built from, wherever it runs: here from a
// folder that is no git checkout at all.
TEST(Certify, RecordsTheCommitOfTheBuildNotOfTheWorkingDirectory) {
  const fs::path away = fresh_temp_dir("certify_elsewhere"), out = away / "out";
  const fs::path here = fs::current_path();
  fs::current_path(away);
  CertifyOptions o = small(FDH_SOURCE_DIR "/corpus", out);
  o.per_family = 1;
  o.soups = 1;
  o.scene_frames = 1;
  const Certificate c = certify(o);
  fs::current_path(here);
  EXPECT_EQ(c.commit, build_commit());
}

}  // namespace
}  // namespace fdh::verify

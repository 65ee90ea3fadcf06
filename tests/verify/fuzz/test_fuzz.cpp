// fdhcert fuzz: the same cases whatever the workers or shards, and a SIGKILL loses nothing.
#include "fdh/fuzz/fuzz.hpp"
#include "fdh/os/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <sys/file.h>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <climits>
#include <thread>

#include "fdh/check/checker.hpp"
#include "fdh/check/metamorphic.hpp"
#include "fdh/io/query_io.hpp"

#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

fs::path fuzz_dir(const std::string& name) {
  return fresh_temp_dir(name);
}

FuzzOptions options(const fs::path& out, int threads) {
  FuzzOptions o;
  o.method = "paper-intended";
  o.family = "parallel-cross";
  o.seed = 7;
  o.count = 1200;
  o.chunk = 100;
  o.threads = threads;
  o.out_dir = out.string();
  return o;
}

// The case files (relative names) and their contents.
std::map<std::string, std::string> cases_in(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (!e.is_regular_file() || rel.rfind(".fuzz", 0) == 0) continue;
    std::ifstream in(e.path());
    std::stringstream ss;
    ss << in.rdbuf();
    out[rel] = ss.str();
  }
  return out;
}

// fdhcert with these arguments as a child process, its standard output discarded.
ChildProcess spawn_fdhcert(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {FDHCERT_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> a;
  for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  return ChildProcess([&] {
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    ::execv(a[0], a.data());
    return 127;
  });
}

// The done-markers (cases-B-E) under out/.fuzz.
long marker_count(const fs::path& out) {
  long n = 0;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(out / ".fuzz", ec))
    n += e.path().filename().string().rfind("cases-", 0) == 0;
  return n;
}

// Runs `fdhcert fuzz args` into `out`, kills it with SIGKILL once `markers` chunks are done,
// checks that every file left is whole, and runs it again to the end. The markers done before
// the kill.
long kill_and_restart(const std::vector<std::string>& args, const fs::path& out, long markers) {
  ChildProcess run = spawn_fdhcert(args);
  for (int i = 0; i < 2000 && marker_count(out) < markers; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  run.kill();
  EXPECT_TRUE(WIFSIGNALED(run.wait().raw));
  const long done_before = marker_count(out);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // workers die with the parent
  // Every file left behind is whole: a case file parses. Temporaries live in .fuzz/tmp only.
  for (const auto& [rel, text] : cases_in(out))
    EXPECT_NO_THROW(read_native((out / rel).string())) << rel;
  EXPECT_TRUE(spawn_fdhcert(args).wait().ok());
  return done_before;
}

// The run of `o` (already run whole into `whole`) as fdhcert, into `killed`: killed after
// `markers` chunks and restarted, it ends with exactly the whole run's case files.
void expect_kill_loses_nothing(const FuzzOptions& o, const fs::path& whole, const fs::path& killed,
                               long markers) {
  std::vector<std::string> args = {"fuzz",
                                   "--method",
                                   o.method,
                                   "--family",
                                   o.family,
                                   "--seed",
                                   std::to_string(o.seed),
                                   "--count",
                                   std::to_string(o.count),
                                   "--chunk",
                                   std::to_string(o.chunk),
                                   "--threads",
                                   std::to_string(o.threads),
                                   "--out",
                                   killed.string()};
  if (o.toi) {
    char tolerance[40];
    std::snprintf(tolerance, sizeof tolerance, "%a", o.toi_tolerance);
    args.insert(args.end(), {"--toi", "--toi-tolerance", tolerance});
  }
  const long done_before = kill_and_restart(args, killed, markers);
  EXPECT_GT(done_before, 0);
  EXPECT_LT(done_before, o.count / o.chunk) << "the run finished before it could be killed";
  EXPECT_EQ(cases_in(killed), cases_in(whole));
}

TEST(Fuzz, FindsShrinksAndStoresCasesThatReplayAsFailures) {
  const fs::path d = fuzz_dir("fuzz_basic");
  const FuzzSummary s = run_fuzz(options(d, 1));
  EXPECT_EQ(s.cases, 1200);
  EXPECT_GT(s.disagreements, 0);
  ASSERT_FALSE(s.distinct.empty());
  EXPECT_LT(s.distinct.size(), std::size_t(s.disagreements));  // shrinking merges cases
  for (const std::string& f : s.distinct) {
    const QueryRecord q = read_native(f).at(0);
    EXPECT_TRUE(q.has_truth());
    EXPECT_TRUE(q.query.is_static_vf());
  }
}

// At δ > 0 the paper's readings answer nothing (n/a): the run that finds their contact
// disagreements above finds none, and its run folder records δ.
TEST(Fuzz, AtMinDistanceThePaperMethodsAreNotApplicable) {
  const fs::path d = fuzz_dir("fuzz_min_distance");
  FuzzOptions o = options(d, 1);
  o.count = 300;
  o.min_distance = 0x1p-20;
  const FuzzSummary s = run_fuzz(o);
  EXPECT_EQ(s.cases, 300);
  EXPECT_EQ(s.disagreements, 0);
  EXPECT_TRUE(fs::is_directory(d / ".fuzz" /
                               "d0x1p-20.paper-intended.parallel-cross.seed7.count300.shard1of1"));
  EXPECT_EQ(run_fuzz(o).resumed, 300);  // the same δ resumes the same run
}

TEST(Fuzz, SameCasesForAnyWorkerCountAndShards) {
  const fs::path one = fuzz_dir("fuzz_one"), two = fuzz_dir("fuzz_two"),
                 shards = fuzz_dir("fuzz_shards");
  const FuzzSummary a = run_fuzz(options(one, 1));
  const FuzzSummary b = run_fuzz(options(two, 2));
  EXPECT_EQ(a.disagreements, b.disagreements);
  EXPECT_EQ(cases_in(one), cases_in(two));
  long disagreements = 0;
  for (int i = 0; i < 3; ++i) {
    FuzzOptions o = options(shards, 1);
    o.shard = i;
    o.shards = 3;
    disagreements += run_fuzz(o).disagreements;
  }
  EXPECT_EQ(disagreements, a.disagreements);
  EXPECT_EQ(cases_in(shards), cases_in(one));
}

TEST(Fuzz, KilledWithSigkillAndRestartedLosesNothing) {
  const fs::path whole = fuzz_dir("fuzz_whole"), killed = fuzz_dir("fuzz_killed");
  FuzzOptions o = options(whole, 2);
  o.count = 6000;
  const FuzzSummary expected = run_fuzz(o);

  // Kill it mid-run: once some chunks are done but not all.
  expect_kill_loses_nothing(o, whole, killed, 5);
  o.out_dir = killed.string();
  const FuzzSummary after = run_fuzz(o);  // all done: reads the markers only
  EXPECT_EQ(after.resumed, 6000);
  EXPECT_EQ(after.disagreements, expected.disagreements);
  EXPECT_EQ(after.distinct.size(), expected.distinct.size());
}

// The moving half of fuzz keeps the same guarantee: float-cubic on a moving edge-edge family,
// killed with SIGKILL part way and started again, ends with exactly the uninterrupted run's cases.
TEST(Fuzz, MovingRunKilledWithSigkillAndRestartedLosesNothing) {
  const fs::path whole = fuzz_dir("fuzz_moving_whole"), killed = fuzz_dir("fuzz_moving_killed");
  FuzzOptions o = options(whole, 2);
  o.method = "float-cubic";
  o.family = "parallel-edges";
  o.count = 2000;
  o.chunk = 50;
  const FuzzSummary expected = run_fuzz(o);
  ASSERT_FALSE(expected.distinct.empty());
  for (const std::string& f : expected.distinct)
    EXPECT_EQ(read_native(f).at(0).query.kind, QueryKind::EdgeEdge) << f;

  expect_kill_loses_nothing(o, whole, killed, 4);
}

// The distinct case files of a run of `method` on `family` over `count` cases into a fresh
// folder `name`.
std::set<std::string> cases_found(const std::string& name, const std::string& method,
                                  const std::string& family, long count, bool metamorphic) {
  FuzzOptions o = options(fuzz_dir(name), 2);
  o.method = method;
  o.family = family;
  o.count = count;
  o.metamorphic = metamorphic;
  return run_fuzz(o).distinct;
}

std::string first_line(const std::string& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// A stored moving case carries the exact CCD contact time and the twin's truth.
TEST(Fuzz, MovingCasesCarryTheExactContactTime) {
  const std::set<std::string> found =
      cases_found("fuzz_moving_time", "float-cubic", "random-linear", 3000, false);
  ASSERT_FALSE(found.empty());
  for (const std::string& f : found) {
    const std::string first = first_line(f);
    const QueryRecord q = read_native(f).at(0);
    ASSERT_TRUE(q.has_truth());
    const bool hit = q.truth == Truth::Yes;
    EXPECT_EQ(first.rfind("# float-cubic says ", 0), 0u) << first;
    EXPECT_NE(first.find(hit ? ", exact says hit (" : ", exact says no."), std::string::npos)
        << first;
    if (hit) {
      EXPECT_NE(first.find("at t "), std::string::npos) << first;
    }
  }
}

// Shrinking keeps the direction of a disagreement: linear-system's false alarms and misses on
// sliver are both stored, each as <direction>-<hash>.vf whose query still fails that way, named
// in its comment and id; the summary's counts by direction add up to the disagreements.
TEST(Fuzz, FalseAlarmsAndMissesAreStoredApart) {
  FuzzOptions o = options(fuzz_dir("fuzz_directions"), 2);
  o.method = "linear-system";
  o.family = "sliver";
  o.count = 300;
  const FuzzSummary s = run_fuzz(o);
  const Method m = select_methods({"linear-system"}).front();
  std::map<std::string, int> stored;
  for (const std::string& f : s.distinct) {
    SCOPED_TRACE(f);
    const std::string name = fs::path(f).filename().string();
    const std::string dir = name.substr(0, name.find('-'));
    ++stored[dir];
    const QueryRecord r = read_native(f).at(0);
    EXPECT_TRUE(r.query.is_static_vf());  // the family's kind
    const Verdicts v = check(m, r.query);
    EXPECT_EQ(dir, v.said && !v.twin ? "fp" : !v.said && v.twin ? "fn" : "agree");
    EXPECT_EQ(r.id, "linear-system/sliver/" + dir);
    EXPECT_NE(first_line(f).find(dir == "fp" ? ": a false alarm (FP)." : ": a miss (FN)."),
              std::string::npos)
        << first_line(f);
  }
  EXPECT_GT(stored["fp"], 0);
  EXPECT_GT(stored["fn"], 0);
  long counted = 0;
  for (const auto& [cls, n] : s.by_class) {
    EXPECT_TRUE(cls == "fp" || cls == "fn") << cls;
    EXPECT_GE(n, stored[cls]);
    counted += n;
  }
  EXPECT_EQ(counted, s.disagreements);
}

// The markers of the run in `out` (names cases-B-E), as paths.
std::vector<fs::path> fuzz_markers_in(const fs::path& out) {
  std::vector<fs::path> v;
  for (const auto& e : fs::recursive_directory_iterator(out / ".fuzz"))
    if (e.path().filename().string().rfind("cases-", 0) == 0) v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

// fuzz --metamorphic: cases where the method's verdict changes under a transform, shrunk and
// stored apart (metamorphic/<method>/<family>) with the transform named; the mode is part of
// the run's manifest.
// A run stored before directions were named (markers listing <hash>.vf) still reads: resumed
// with its options, it runs nothing and counts its disagreements as unclassed.
TEST(Fuzz, ARunStoredBeforeDirectionsReadsAsUnclassed) {
  const fs::path d = fuzz_dir("fuzz_unclassed");
  FuzzOptions o = options(d, 1);
  o.count = 200;
  const FuzzSummary first = run_fuzz(o);
  ASSERT_GT(first.disagreements, 0);
  for (const fs::path& m : fuzz_markers_in(d)) {  // as the older fuzz wrote them
    std::string text = [&] {
      std::ifstream in(m);
      std::stringstream ss;
      ss << in.rdbuf();
      return ss.str();
    }();
    for (std::size_t at; (at = text.find("/fp-")) != std::string::npos ||
                         (at = text.find("/fn-")) != std::string::npos;)
      text.erase(at + 1, 3);
    std::ofstream(m) << text;
  }
  const FuzzSummary again = run_fuzz(o);
  EXPECT_EQ(again.resumed, 200);
  EXPECT_EQ(again.disagreements, first.disagreements);
  EXPECT_EQ(again.by_class, (std::map<std::string, long>{{"disagrees", first.disagreements}}));
}

TEST(Fuzz, MetamorphicRunStoresVerdictChangesApart) {
  const std::set<std::string> found =
      cases_found("fuzz_metamorphic", "linear-system", "parallel-land", 300, true);
  ASSERT_FALSE(found.empty());
  const Method m = select_methods({"linear-system"}).front();
  for (const std::string& f : found) {
    EXPECT_NE(f.find("/metamorphic/linear-system/parallel-land/"), std::string::npos) << f;
    const std::string first = first_line(f);
    EXPECT_NE(first.find("linear-system says "), std::string::npos) << first;
    EXPECT_NE(first.find(" after "), std::string::npos) << first;
    const QueryRecord r = read_native(f).at(0);
    EXPECT_EQ(r.truth, truth_of(twin_hit(r.query)));
    EXPECT_TRUE(metamorphic_failure(m, r.query)) << f;
  }
  // A case is OUT/metamorphic/linear-system/parallel-land/<hash>.vf; the run is OUT/.fuzz/RUN.
  const fs::path folder = fs::path(*found.begin()).parent_path().parent_path().parent_path();
  const fs::path manifest = folder.parent_path() / ".fuzz" /
                            "metamorphic.linear-system.parallel-land.seed7.count300.shard1of1" /
                            "manifest";
  std::ifstream in(manifest);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("mode metamorphic\n"), std::string::npos) << text.str();
  // The exact twin, under the same search, changes no verdict.
  EXPECT_TRUE(cases_found("fuzz_metamorphic_twin", "exact", "parallel-land", 300, true).empty());
}

TEST(Fuzz, ResumedWithAnotherChunkAndThreadsEndsWithTheSameCases) {
  const fs::path whole = fuzz_dir("fuzz_rechunk_whole"), part = fuzz_dir("fuzz_rechunk_part");
  const FuzzSummary expected = run_fuzz(options(whole, 1));
  // A run killed part way: chunks of 100 done, some not (their markers gone, as after a kill).
  run_fuzz(options(part, 2));
  const std::vector<fs::path> markers = fuzz_markers_in(part);
  ASSERT_EQ(markers.size(), 12u);
  for (std::size_t k : {1u, 2u, 7u, 11u}) fs::remove(markers[k]);
  for (const int chunk : {37, 1000, 1}) {
    FuzzOptions o = options(part, chunk == 37 ? 2 : 1);
    o.chunk = chunk;
    const FuzzSummary s = run_fuzz(o);
    EXPECT_EQ(s.cases, 1200);
    EXPECT_EQ(s.disagreements, expected.disagreements);
    EXPECT_EQ(s.distinct, [&] {
      std::set<std::string> d;
      for (const std::string& f : expected.distinct)
        d.insert((part / fs::relative(f, whole)).string());
      return d;
    }());
    EXPECT_EQ(cases_in(part), cases_in(whole));
    if (chunk == 37) {
      EXPECT_EQ(s.resumed, 800);
      // Cut again, across the old and the new chunk boundaries.
      const std::vector<fs::path> now = fuzz_markers_in(part);
      for (std::size_t k = 0; k < now.size(); k += 3) fs::remove(now[k]);
    }
  }
}

TEST(Fuzz, RefusesToStartBesideAnUnfinishedRunWithOtherOptions) {
  const fs::path d = fuzz_dir("fuzz_other_run");
  run_fuzz(options(d, 1));
  fs::remove(fuzz_markers_in(d).at(3));  // now unfinished
  for (const auto& change : std::vector<std::function<void(FuzzOptions&)>>{
           [](FuzzOptions& o) { o.seed = 8; }, [](FuzzOptions& o) { o.count = 1300; },
           [](FuzzOptions& o) { o.method = "paper-literal"; },
           [](FuzzOptions& o) { o.family = "angled"; },
           [](FuzzOptions& o) { o.metamorphic = true; },
           [](FuzzOptions& o) { o.shard = 1, o.shards = 2; }}) {
    FuzzOptions o = options(d, 1);
    change(o);
    try {
      run_fuzz(o);
      ADD_FAILURE() << "a run with other options started beside an unfinished one";
    } catch (const FuzzRefused& e) {
      EXPECT_NE(std::string(e.what()).find("unfinished fuzz run with other options (--method "
                                           "paper-intended --family parallel-cross --seed 7 "
                                           "--count 1200 --shard 1/1)"),
                std::string::npos)
          << e.what();
    }
  }
  // The same run, with another chunk, resumes it; then a run with other options may start.
  FuzzOptions same = options(d, 2);
  same.chunk = 450;
  EXPECT_EQ(run_fuzz(same).resumed, 1100);
  FuzzOptions other = options(d, 1);
  other.seed = 8;
  other.count = 100;
  EXPECT_EQ(run_fuzz(other).cases, 100);
}

TEST(Fuzz, RefusesAManifestThatDoesNotRecordItsRun) {
  const fs::path d = fuzz_dir("fuzz_manifest");
  FuzzOptions o = options(d, 1);
  o.count = 100;
  run_fuzz(o);
  const fs::path manifest = fuzz_markers_in(d).at(0).parent_path() / "manifest";
  ASSERT_TRUE(fs::exists(manifest));
  std::ofstream(manifest) << "fdhcert fuzz run\nmethod paper-intended\nfamily parallel-cross\n"
                             "seed 9\ncount 100\nshard 1/1\n";
  EXPECT_THROW(run_fuzz(o), FuzzRefused);
}

TEST(Fuzz, ASecondRunOnTheSameFolderRefuses) {
  const fs::path d = fuzz_dir("fuzz_locked");
  fs::create_directories(d / ".fuzz");
  const int fd = ::open((d / ".fuzz" / "lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as a running fuzz run holds it
  FuzzOptions o = options(d, 1);
  o.lock_wait_seconds = 0.2;
  try {
    run_fuzz(o);
    ADD_FAILURE() << "ran beside a run holding the lock";
  } catch (const FuzzRefused& e) {
    EXPECT_NE(std::string(e.what()).find("another fuzz run is using " + d.string()),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(d / "paper-intended")) << "wrote before it had the lock";
  ::close(fd);
  o.count = 100;
  EXPECT_EQ(run_fuzz(o).cases, 100);
}

TEST(Fuzz, CleanUpRemovesOnlyItsOwnTemporaries) {
  const fs::path d = fuzz_dir("fuzz_cleanup");
  const fs::path cases = d / "paper-intended" / "parallel-cross";
  fs::create_directories(cases);
  fs::create_directories(d / ".fuzz" / "tmp");
  const std::vector<fs::path> users = {d / "notes.tmp.1.2", cases / "mine.vf.tmp.12.0",
                                       d / "sub" / "x.tmp.3.4"};
  for (const fs::path& p : users) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "the user's\n";
  }
  std::ofstream(d / ".fuzz" / "tmp" / "123.4") << "half a case";  // a killed run's
  FuzzOptions o = options(d, 2);
  o.count = 300;
  run_fuzz(o);
  for (const fs::path& p : users) EXPECT_TRUE(fs::exists(p)) << p;
  EXPECT_TRUE(fs::is_empty(d / ".fuzz" / "tmp"));
}

TEST(Fuzz, RefusesATemporaryFolderThatIsALink) {
  const fs::path d = fuzz_dir("fuzz_tmp_link"), elsewhere = fuzz_dir("fuzz_tmp_elsewhere");
  std::ofstream(elsewhere / "precious") << "the user's\n";
  fs::create_directories(d / ".fuzz");
  fs::create_directory_symlink(elsewhere, d / ".fuzz" / "tmp");
  EXPECT_THROW(run_fuzz(options(d, 1)), std::runtime_error);
  EXPECT_TRUE(fs::exists(elsewhere / "precious"));
}

TEST(Fuzz, ShardBoundsDoNotOverflow) {
  const auto exact = [](long count, int shard, int shards) {
    return long(static_cast<unsigned __int128>(count) * unsigned(shard) / unsigned(shards));
  };
  for (const long count : {0L, 1L, 999L, 1L << 40, 1000000000000L, LONG_MAX})
    for (const int shards : {1, 3, 1000000, INT_MAX})
      for (const int shard : {0, 1, shards / 2, shards - 1, shards})
        EXPECT_EQ(shard_begin(count, shard, shards), exact(count, shard, shards))
            << count << " " << shard << "/" << shards;
  EXPECT_THROW(shard_begin(-1, 0, 1), std::invalid_argument);
  EXPECT_THROW(shard_begin(5, 2, 1), std::invalid_argument);
  // The last shard of the largest run ends at its count.
  EXPECT_EQ(shard_begin(1L << 40, 1000000, 1000000), 1L << 40);
}

// fuzz --toi on float-cubic over `family`: the options of a run into a fresh folder `name`.
FuzzOptions toi_options(const std::string& name, const std::string& family, long count) {
  FuzzOptions o = options(fuzz_dir(name), 2);
  o.method = "float-cubic";
  o.family = family;
  o.count = count;
  o.chunk = 50;
  o.toi = true;
  return o;
}

// The class a case file of fuzz --toi names: "late" for toi/float-cubic/F/late-<hash>.vf.
std::string class_of(const std::string& file) {
  const std::string name = fs::path(file).filename().string();
  return name.substr(0, name.find('-'));
}

// fuzz --toi finds float-cubic's late times; each stored case, shrunk, is still late (t_lo
// after t*, not a missed contact), and its file says so with the exact contact time.
TEST(FuzzToi, FindsLateFloatCubicTimesThatStayLateWhenShrunk) {
  const FuzzOptions o = toi_options("fuzz_toi_late", "coplanar", 300);
  const FuzzSummary s = run_fuzz(o);
  EXPECT_EQ(o.toi_tolerance, kDefaultToiTolerance);
  const Method m = select_methods({"float-cubic"}).front();
  int late = 0;
  for (const std::string& f : s.distinct) {
    SCOPED_TRACE(f);
    EXPECT_NE(f.find("/toi/float-cubic/coplanar/"), std::string::npos);
    const QueryRecord r = read_native(f).at(0);
    const TimeCheck c = check_time(m, r.query, o.toi_width);
    const std::string cls = class_of(f);
    ASSERT_TRUE(r.has_truth());
    EXPECT_EQ(r.truth == Truth::Yes, c.twin.hit);
    if (cls == "late") {
      ++late;
      EXPECT_TRUE(c.late && c.said.hit);
      EXPECT_EQ(first_line(f).rfind("# TOI late: float-cubic's TOI is late: t_lo = ", 0), 0u)
          << first_line(f);
      EXPECT_NE(first_line(f).find("exact says hit (at t "), std::string::npos);
    } else {
      EXPECT_EQ(cls, "missed");
      EXPECT_TRUE(c.late && !c.said.hit);
    }
  }
  EXPECT_GE(late, 3);
}

// A case is shrunk within its class: with a tolerance of 0, float-cubic's early times shrink to
// early times, never to late ones or missed contacts; the exact twin and robust keep their
// promise on every case.
TEST(FuzzToi, EarlyCasesShrinkToEarlyCases) {
  FuzzOptions o = toi_options("fuzz_toi_early", "random-linear", 300);
  o.toi_tolerance = 0;
  const FuzzSummary s = run_fuzz(o);
  const Method m = select_methods({"float-cubic"}).front();
  int early = 0;
  for (const std::string& f : s.distinct) {
    SCOPED_TRACE(f);
    const Query q = read_native(f).at(0).query;
    const TimeCheck c = check_time(m, q, o.toi_width);
    if (class_of(f) == "early") {
      ++early;
      EXPECT_TRUE(c.kept && !c.late && c.early > 0);
    }
    for (const Method& p : time_promised_methods()) EXPECT_TRUE(check_time(p, q, o.toi_width).kept);
  }
  EXPECT_GE(early, 3);
  // At the default tolerance none of them is a finding.
  o.out_dir = fuzz_dir("fuzz_toi_early_default").string();
  o.toi_tolerance = kDefaultToiTolerance;
  for (const std::string& f : run_fuzz(o).distinct) EXPECT_NE(class_of(f), "early") << f;
}

// Same seed, same cases, for any number of workers; other tolerances are another run.
TEST(FuzzToi, SameSeedSameCases) {
  FuzzOptions a = toi_options("fuzz_toi_a", "sliding-on-edge", 200);
  FuzzOptions b = toi_options("fuzz_toi_b", "sliding-on-edge", 200);
  b.threads = 1;
  b.chunk = 70;
  const FuzzSummary sa = run_fuzz(a), sb = run_fuzz(b);
  EXPECT_GT(sa.disagreements, 0);
  EXPECT_EQ(sa.disagreements, sb.disagreements);
  EXPECT_EQ(cases_in(a.out_dir), cases_in(b.out_dir));
  // The mode, width and tolerance are in the run's name and manifest.
  const fs::path run = fs::path(a.out_dir) / ".fuzz" /
                       "toi.w0x1p-30.tol0x1.999999999999ap-4.float-cubic.sliding-on-edge.seed7."
                       "count200.shard1of1" /
                       "manifest";
  std::ifstream in(run);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("mode toi\nwidth 0x1p-30\ntoi-tolerance 0x1.999999999999ap-4\n"),
            std::string::npos)
      << text.str();
  // Another tolerance on the same folder is another run: refused while this one is unfinished.
  fs::remove(fuzz_markers_in(a.out_dir).at(1));
  FuzzOptions other = a;
  other.toi_tolerance = 0;
  EXPECT_THROW(run_fuzz(other), FuzzRefused);
}

// fuzz --toi killed with SIGKILL and started again ends with the uninterrupted run's cases.
TEST(FuzzToi, KilledWithSigkillAndRestartedLosesNothing) {
  const FuzzOptions o = toi_options("fuzz_toi_whole", "coplanar", 2000);
  ASSERT_FALSE(run_fuzz(o).distinct.empty());
  expect_kill_loses_nothing(o, o.out_dir, fuzz_dir("fuzz_toi_killed"), 4);
}

// --toi asks for a moving family, a method that gives a time, and not --metamorphic.
TEST(FuzzToi, RefusesWhatItCannotCheck) {
  FuzzOptions o = toi_options("fuzz_toi_bad", "angled", 10);
  EXPECT_THROW(run_fuzz(o), std::invalid_argument);  // static family
  o.family = "coplanar";
  o.method = "paper-literal";
  EXPECT_THROW(run_fuzz(o), std::invalid_argument);  // no time of impact
  o.method = "float-cubic";
  o.metamorphic = true;
  EXPECT_THROW(run_fuzz(o), std::invalid_argument);
}

}  // namespace
}  // namespace fdh::verify

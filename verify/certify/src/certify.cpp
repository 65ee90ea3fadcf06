#include "fdh/certify/certify.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include "fdh/bvh.hpp"
#include "fdh/certify/certify_metamorphic.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/check/parallel.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/exact/kdop.hpp"
#include "fdh/exact/versions.hpp"
#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/gen/soup.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/record_scope.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/io/scene_schema.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/build_info.hpp"
#include "fdh/scene/scene_report.hpp"
#include "fdh/scene/scene_run.hpp"

#include "certifier.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;
namespace {

// A shipped scene run with robust as its narrow phase (and its self-collision pass, if it has
// one): what the narrow-phase queries of every stride-th frame add to the certificate.
CertifyTally scene_tally(const std::string& file, const CertifyOptions& o, const Certifier& cert) {
  const cloth::Scene scene = read_scene(file);
  SceneRunOptions opt;  // robust, k = 18, the scene's step as `simulate` takes it
  // At most 4e5 particle-frames (quick) or 4e6: every shipped 25x25 scene whole, the fold
  // scene's first frames only (its narrow phase makes tens of thousands of queries a frame
  // once it lands; its full run is `fdhcert scenes`', with the exact audit).
  opt.frames = bounded_frames(scene, o.scene_frames, o.quick ? 400000 : 4000000);
  opt.check = false;  // certified here instead
  CertifyTally sum = cert.zero();
  opt.on_frame = [&](const cloth::Simulation& sim, int f) {
    if (f % o.scene_stride) return;
    std::vector<QueryRecord> qs;
    for (const auto& nq : sim.queries()) {
      QueryRecord q;
      q.query = sim.query(nq);
      q.id = scene.name + "/f" + std::to_string(f) + "p" + std::to_string(nq.particle) + "t" +
             std::to_string(nq.triangle);
      q.file = file;
      qs.push_back(std::move(q));
    }
    sum.add(cert.tally(qs));
  };
  run_scene(scene, opt);
  return sum;
}

void tell(const Certificate& c, const std::string& stage, long done, long total) {
  const std::string unit = stage == "generator families" || stage == "minimum separation" ||
                                   stage == "corpus" || stage == "extra files"
                               ? "queries"
                           : stage == "scenes" ? "scenes"
                           : total > 0         ? "files"
                                               : "";
  report(c.options.progress, {stage, done, total, unit});
}

// The budget stopped `stage` after `done` of `total` (fdh/os/budget.hpp); nothing if it did not.
void note_cut(Certificate& c, const std::string& stage, long done, long total,
              const std::string& unit) {
  if (c.options.budget.spent() && done < total) c.cut_short.push_back({stage, done, total, unit});
}

// Every shipped scene, each on a core of its own (their cloths are independent; a cloth of
// 64x64 and more also runs its step on every core), counted in the scenes' order.
void check_scenes(Certificate& c, Certifier& cert) {
  const fs::path dir = fs::path(c.options.corpus_dir) / "scenes";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  const std::vector<std::string> files = scene_files(dir.string());
  if (c.options.budget.spent()) return note_cut(c, "scenes", 0, long(files.size()), "scenes");
  tell(c, "scenes", 0, long(files.size()));
  const auto scenes = parts_in_order(files.size(), 1, cert.zero(),
                                     [&](std::size_t i, std::size_t, CertifyTally& t) {
                                       t = scene_tally(files[i], c.options, cert);
                                     });
  long whole = 0;  // scenes whose queries were all checked
  for (const CertifyTally& t : scenes) {
    ++c.scenes;
    whole += t.skipped == 0;
    c.scene_queries += t.queries;
    cert.record(t);
  }
  note_cut(c, "scenes", whole, long(files.size()), "scenes");
}

PeerOptions peer_options(const CertifyOptions& o) {
  PeerOptions p;
  p.quick = o.quick;
  p.seed = o.seed;
  p.cases = o.peer_cases;
  p.save_dir = (fs::path(o.files_dir()) / "peers").string();
  p.saved_name = (fs::path(o.out_dir) / "peers").string();
  p.replay_dir = (fs::path(o.corpus_dir) / "peers").string();
  return p;
}

// Queries of `files`, read first (so that progress and a cut can say of how many queries), then
// checked in batches while the budget lasts; progress counts queries.
long check_files(Certificate& c, Certifier& cert, const std::string& stage,
                 const std::vector<std::vector<QueryRecord>>& files) {
  long total = 0, done = 0;
  for (const auto& qs : files) total += long(qs.size());
  const std::size_t batch = 64;  // a slow plug-in's progress, between queries
  for (const auto& qs : files)
    for (std::size_t i = 0; i < qs.size(); i += batch) {
      tell(c, stage, done, total);
      const std::size_t end = std::min(qs.size(), i + batch);
      done +=
          cert.check_queries({qs.begin() + std::ptrdiff_t(i), qs.begin() + std::ptrdiff_t(end)});
    }
  note_cut(c, stage, done, total, "queries");
  return done;
}

void check_corpus(Certificate& c, Certifier& cert,
                  const std::vector<std::vector<QueryRecord>>& files) {
  c.corpus_files = long(files.size());
  c.corpus_queries = check_files(c, cert, "corpus", files);
}

// per_family queries of every family, family j from stream j, in batches: drawn on this thread
// (RapidCheck's generators share global state), checked on every core.
void check_families(Certificate& c, Certifier& cert) {
  const long total = long(all_families().size()) * c.options.per_family, batch = 400;
  std::uint64_t stream = 0;
  for (const Family& f : all_families()) {
    (f.moving ? c.moving_families : c.families).push_back(f.name);
    ++stream;
    for (long i = 0; i < c.options.per_family && !c.options.budget.spent(); i += batch) {
      tell(c, "generator families", c.fuzzed_queries, total);
      std::vector<QueryRecord> qs;
      for (long j = i; j < std::min(i + batch, c.options.per_family); ++j)
        qs.push_back(generate(f, case_seed(c.options.seed * 1000 + stream, j)).record());
      c.fuzzed_queries += cert.check_queries(qs);
    }
  }
  note_cut(c, "generator families", c.fuzzed_queries, total, "queries");
}

// Drawn on this thread (RapidCheck), checked on every core.
void check_soups(Certificate& c, Certifier& cert) {
  const std::uint64_t s = c.options.seed * 1000 + 999;
  if (c.options.budget.spent()) return note_cut(c, "tree soups", 0, c.options.soups, "pairs");
  tell(c, "tree soups", 0, 0);
  std::vector<Soup> a, b;
  for (long i = 0; i < c.options.soups; ++i) {
    a.push_back(generate_soup(24, case_seed(s, 2 * i)));
    b.push_back(generate_soup(24, case_seed(s, 2 * i + 1)));
  }
  cert.check_soups(a, b);
}

// The query files certify reads, each file's queries in order.
struct QueryFiles {
  std::vector<std::vector<QueryRecord>> corpus, extra;
};

// Every input read before any work (issue 34), before the output folder is made: a bad corpus
// file, scene or extra file is refused at once, not after the stages before it. The corpus and
// the extra files are kept for their stages; the scenes (a few lines each) are read again by
// theirs.
QueryFiles read_inputs_first(const CertifyOptions& o) {
  QueryFiles in;
  for (const std::string& f : list_query_files(o.corpus_dir)) in.corpus.push_back(read_native(f));
  const fs::path scenes = fs::path(o.corpus_dir) / "scenes";
  std::error_code ec;  // a corpus that is a link loop is refused by its reader, by name
  if (fs::is_directory(scenes, ec))
    for (const std::string& f : scene_files(scenes.string())) (void)read_scene(f);
  for (const std::string& f : o.extra_files) in.extra.push_back(read_query_file(f));
  return in;
}

void check_extra_files(Certificate& c, Certifier& cert,
                       const std::vector<std::vector<QueryRecord>>& extra) {
  c.extra_queries = check_files(c, cert, "extra files", extra);
}

// The δ a contact query is asked at again: the D given, else 2^-20 of the query's scale (the
// power of two at or above its largest coordinate), exact; 0 where that underflows.
double stage_delta(const Query& q, double given) {
  if (given > 0) return given;
  double top = 0;
  for (const Vec3& p : q.x) top = std::max({top, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  int e = 0;
  std::frexp(top == 0 ? 1.0 : top, &e);
  const double d = std::ldexp(1.0, e - 20);
  return std::isnormal(d) ? d : 0;
}

// Every 8th of `qs` asked again at the stage's δ (their truths are contact's: dropped).
std::vector<QueryRecord> at_delta(const std::vector<QueryRecord>& qs, double given) {
  std::vector<QueryRecord> out;
  for (std::size_t i = 0; i < qs.size(); i += 8) {
    QueryRecord r = qs[i];
    r.query.min_distance = stage_delta(r.query, given);
    r.truth = Truth::Unknown;
    if (r.query.min_distance > 0) out.push_back(std::move(r));
  }
  return out;
}

// The minimum-separation stage (DeltaStage): a quarter of per_family queries of each delta-
// family (stream 500 + j), then every 8th corpus query and every 8th of each contact family's
// first per_family / 2 cases, at δ.
void check_delta(Certificate& c) {
  DeltaStage& d = c.delta;
  d.min_distance = c.options.min_distance;
  if (c.options.min_distance == 0) return;
  if (c.options.budget.spent()) return c.cut_short.push_back({"minimum separation", 0, 0, ""});
  d.run = true;
  Certifier cert(c, true);
  const long per = std::max(1L, c.options.per_family / 4);
  std::uint64_t stream = 500;
  for (const Family& f : delta_families()) {
    d.families.push_back(f.name);
    tell(c, "minimum separation", d.family_queries, per * long(delta_families().size()));
    std::vector<QueryRecord> qs;
    for (long j = 0; j < per; ++j)
      qs.push_back(generate(f, case_seed(c.options.seed * 1000 + stream, j)).record());
    ++stream;
    d.family_queries += cert.check_queries(qs);
  }
  for (const std::string& f : list_query_files(c.options.corpus_dir))
    d.contact_queries += cert.check_queries(at_delta(read_native(f), c.options.min_distance));
  stream = 0;
  for (const Family& f : all_families()) {
    std::vector<QueryRecord> qs;
    ++stream;
    for (long j = 0; j < c.options.per_family / 2; ++j)
      qs.push_back(generate(f, case_seed(c.options.seed * 1000 + stream, j)).record());
    d.contact_queries += cert.check_queries(at_delta(qs, c.options.min_distance));
  }
  if (c.options.budget.spent())
    c.cut_short.push_back(
        {"minimum separation", d.family_queries + d.contact_queries, 0, "queries"});
}

// The metamorphic checks ran with the queries of the query stages: once the budget stopped one
// of those, the transforms of the queries not reached were not checked either. Said after the
// last cut of a query stage.
void note_metamorphic_cut(Certificate& c) {
  if (!c.options.runs("metamorphic")) return;
  const auto after = std::find_if(c.cut_short.rbegin(), c.cut_short.rend(), [](const BudgetCut& b) {
    return b.stage != "minimum separation" && b.stage != "peers";
  });
  if (after == c.cut_short.rend()) return;
  long checked = 0;  // transformed queries, each once however many methods were asked on it
  for (const TransformCount& t : c.metamorphic_transforms) checked += t.applied;
  c.cut_short.insert(after.base(), {"metamorphic", checked, 0, "transformed queries"});
}

void check_peers(Certificate& c) {
  if (c.options.budget.spent()) return c.cut_short.push_back({"peers", 0, 0, ""});  // not run
  tell(c, "peers", 0, 0);
  c.peers = certify_peers(peer_options(c.options));
  if (c.first_violation.empty()) c.first_violation = c.peers.first_own_violation;
}

// The stages of `names`, in that order; metamorphic is a flag of the query stages.
void run_stages(Certificate& c, Certifier& cert, const std::vector<std::string>& names,
                const QueryFiles& in) {
  for (const std::string& s : names) {
    if (s == "corpus") check_corpus(c, cert, in.corpus);
    if (s == "families") check_families(c, cert);
    if (s == "scenes") check_scenes(c, cert);
    if (s == "soups") check_soups(c, cert);
    if (s == "extra") check_extra_files(c, cert, in.extra);
    if (s == "min-distance") check_delta(c);
    if (s == "peers") check_peers(c);
  }
  note_metamorphic_cut(c);
}

}  // namespace

const std::vector<std::string>& certify_stages() {
  static const std::vector<std::string> names = {"corpus", "families",    "scenes",       "soups",
                                                 "extra",  "metamorphic", "min-distance", "peers"};
  return names;
}

bool CertifyOptions::runs(const std::string& stage) const {
  return stages.empty() || std::find(stages.begin(), stages.end(), stage) != stages.end();
}

Certificate certify(const CertifyOptions& options) {
  Certificate c;
  c.options = options;
  if (c.options.per_family < 0) c.options.per_family = options.quick ? 200 : 3000;
  if (c.options.soups < 0) c.options.soups = options.quick ? 30 : 300;
  if (!c.options.runs("soups")) c.options.soups = 0;  // none checked: none claimed
  if (c.options.scene_frames < 0) c.options.scene_frames = options.quick ? 600 : kMaxFrames;
  if (c.options.scene_stride < 1) c.options.scene_stride = options.quick ? 50 : 10;
  c.commit = build_commit();
  c.cgal = exact::cgal_library_version();
  c.gmp = exact::gmp_library_version();
  const QueryFiles inputs = read_inputs_first(c.options);
  for (const CertifiedPlugin& p : c.options.plugins)  // the probe counts in the budget too
    if (p.probe_cut)
      c.cut_short.push_back({"probe of plug-in " + p.name, p.probe_calls, 0, "calls"});
  Certifier cert(c);
  run_stages(c, cert, c.options.stages.empty() ? certify_stages() : c.options.stages, inputs);
  return c;
}

}  // namespace fdh::verify

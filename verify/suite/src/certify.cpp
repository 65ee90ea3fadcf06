#include "fdh/suite/certify.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "fdh/bvh.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/exact/kdop.hpp"
#include "fdh/exact/versions.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/gen/soup.hpp"
#include "fdh/io/atomic_file.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_file.hpp"
#include "fdh/suite/build_info.hpp"
#include "fdh/suite/certify_metamorphic.hpp"
#include "fdh/suite/fuzz.hpp"
#include "fdh/suite/scene_report.hpp"
#include "fdh/suite/scene_run.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;
namespace {

// Every method with a promise, on every query decision it makes and every box it builds, against
// the exact twin through the checker (check/checker.hpp).
class Certifier {
 public:
  explicit Certifier(Certificate& c) : c_(c) {
    fs::create_directories(c.options.out_dir);
    for (const Method& m : methods_)
      for (const Decision d : kQueryDecisions)
        if (m.test[std::size_t(d)]) c_.promises.push_back({m.name, d, m.promise});
    for (const BoxMethod& b : boxes_) {
      c_.boxes.push_back({b.name, b.k});
      c_.boxes.back().tree = b.builds_tree;
    }
  }

  void check_query(const Query& q) {
    check_boxes(q, std::vector<Vec3>(q.x.begin(), q.x.end()));
    if (q.is_static_vf()) {
      check_boxes(q, {q.b0(), q.b1()});
      check_boxes(q, {q.d(), q.e(), q.f()});
    }
    const bool twin = twin_hit(q);
    check_truth(q, twin);
    check_metamorphic(q, twin);
    const Decision d = decision_of(q);
    for (PromiseCheck& p : c_.promises) {
      if (p.decision != d) continue;
      const Method& m = method(p.method);
      const auto& filter = m.filter[std::size_t(d)];
      p.filter_decided += filter && filter(q) != Filtered::Uncertain;
      ++p.checked;
      const Verdicts v = check(m, q, twin);
      if (v.kept) continue;
      ++p.violations;
      Query saved = q;
      saved.truth = twin;
      violation(saved, describe(m, v) + " (" + to_string(d) + ")");
    }
  }

  void check_metamorphic(const Query& q, bool twin) {
    const std::optional<std::string> broken = metamorphic_.check(q);
    if (!broken) return;
    Query saved = q;
    saved.truth = twin;
    violation(saved, *broken);
  }

  void check_truth(const Query& q, bool twin) {
    const std::optional<bool> agrees = twin_matches_truth(q, twin);
    if (!agrees) return;
    ++c_.truths;
    if (*agrees) return;
    ++c_.truth_violations;
    violation(q, "exact says " + std::string(twin ? "hit" : "no") + ", the stored truth says " +
                     (q.truth ? "hit" : "no"));
  }

  // The FDH tree of each certified k culls no pair whose exact k-DOPs overlap.
  void check_soups(const Soup& a, const Soup& b) {
    for (BoxCheck& box : c_.boxes) {
      if (!is_valid_k(box.k) || !box.tree) continue;
      with_k(box.k, [&](auto kc) {
        constexpr int K = decltype(kc)::value;
        const Bvh<K> ta(a.tris, a.x0, a.x1), tb(b.tris, b.x0);
        std::vector<std::pair<int, int>> found;
        traverse(ta, tb, found);
        const auto pairs = exact::overlapping_pairs(K, primitive_corners(a.tris, a.x0, a.x1),
                                                    primitive_corners(b.tris, b.x0, {}));
        ++box.soup_pairs;
        box.exact_pairs += long(pairs.size());
        const auto culled = culled_pairs(std::move(found), pairs);
        if (culled.empty()) return;
        ++box.cull_violations;
        soup_violation(a, b, K, culled.front());
      });
    }
  }

 private:
  const Method& method(const std::string& name) const {
    return *std::find_if(methods_.begin(), methods_.end(),
                         [&](const Method& m) { return m.name == name; });
  }

  void check_boxes(const Query& q, const std::vector<Vec3>& pts) {
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      BoxCheck& box = c_.boxes[i];
      ++box.boxes;
      const int s = check_box(boxes_[i], pts.data(), pts.size());
      if (s < 0) continue;
      ++box.box_violations;
      violation(q, "the " + box.method + " " + std::to_string(box.k) + "-DOP of " +
                       std::to_string(pts.size()) +
                       " of its points misses the exact extent in slab " + std::to_string(s));
    }
  }

  void violation(const Query& q, const std::string& what) {
    if (!c_.first_violation.empty()) return;
    const fs::path file = fs::path(c_.options.out_dir) / ("violation-" + case_hash(q) + ".vf");
    write_file_atomically(file.string(), case_file_text(q, {"certify: " + what + "."}));
    c_.first_violation = what + " (query " + q.id + " from " +
                         (q.file.empty() ? "a generator" : q.file + ":" + std::to_string(q.line)) +
                         "), saved to " + file.string();
  }

  // A missed pair is saved as an OBJ: A at t = 0, A at t = 1 (its swept leaves), and B.
  void soup_violation(const Soup& a, const Soup& b, int k, std::pair<int, int> p) {
    if (!c_.first_violation.empty()) return;
    std::ostringstream os;
    os << "# certify: the " << k << "-DOP tree missed the pair (" << p.first << ", " << p.second
       << ") whose exact " << k << "-DOPs overlap\n";
    int base = 1;
    const auto object = [&](const char* name, const std::vector<Vec3>& x,
                            const std::vector<Tri>& tris) {
      char buf[128];
      os << "o " << name << "\n";
      for (const Vec3& v : x) {
        std::snprintf(buf, sizeof buf, "v %a %a %a\n", v.x, v.y, v.z);
        os << buf;
      }
      for (const Tri& t : tris)
        os << "f " << t[0] + base << ' ' << t[1] + base << ' ' << t[2] + base << "\n";
      base += int(x.size());
    };
    object("A_t0", a.x0, a.tris);
    object("A_t1", a.x1, a.tris);
    object("B", b.x0, b.tris);
    const fs::path file = fs::path(c_.options.out_dir) / "violation-tree.obj";
    write_file_atomically(file.string(), os.str());
    c_.first_violation =
        "the " + std::to_string(k) + "-DOP tree missed a pair, saved to " + file.string();
  }

  Certificate& c_;
  const std::vector<Method> methods_ = promised_methods();
  const std::vector<BoxMethod> boxes_ = all_box_methods();
  MetamorphicCertifier metamorphic_{c_.metamorphic};
};

// Every shipped scene runs with robust as its narrow phase (and its self-collision pass, if it
// has one); the narrow-phase queries of every stride-th frame are certified like any other.
void check_scenes(Certificate& c, Certifier& cert) {
  const fs::path dir = fs::path(c.options.corpus_dir) / "scenes";
  if (!fs::is_directory(dir)) return;
  const int stride = c.options.scene_stride;
  for (const std::string& file : scene_files(dir.string())) {
    const cloth::Scene scene = read_scene(file);
    SceneRunOptions opt;  // robust, k = 18, the scene's step as `simulate` takes it
    // At most 4e5 particle-frames (quick) or 4e6: every shipped 25x25 scene whole, the fold
    // scene's first frames only (its narrow phase makes tens of thousands of queries a frame
    // once it lands; its full run is `fdhcert scenes`', with the exact audit).
    opt.frames = bounded_frames(scene, c.options.scene_frames, c.options.quick ? 400000 : 4000000);
    opt.check = false;  // certified here instead
    opt.on_frame = [&](const cloth::Simulation& sim, int f) {
      if (c.options.progress && f % 10 == 0)
        c.options.progress("scene " + scene.name, f, opt.frames);
      if (f % stride) return;
      for (const auto& nq : sim.queries()) {
        Query q = sim.query(nq);
        q.id = scene.name + "/f" + std::to_string(f) + "p" + std::to_string(nq.particle) + "t" +
               std::to_string(nq.triangle);
        q.file = file;
        ++c.scene_queries;
        cert.check_query(q);
      }
    };
    ++c.scenes;
    run_scene(scene, opt);
  }
}

PeerOptions peer_options(const CertifyOptions& o) {
  PeerOptions p;
  p.quick = o.quick;
  p.seed = o.seed;
  p.cases = o.peer_cases;
  p.save_dir = (fs::path(o.out_dir) / "peers").string();
  p.replay_dir = (fs::path(o.corpus_dir) / "peers").string();
  return p;
}

void tell(const Certificate& c, const std::string& stage, long done, long total) {
  if (c.options.progress) c.options.progress(stage, done, total);
}

void check_corpus(Certificate& c, Certifier& cert) {
  const std::vector<std::string> files = list_query_files(c.options.corpus_dir);
  for (const std::string& f : files) {
    tell(c, "corpus", c.corpus_files++, long(files.size()));
    for (const Query& q : read_native(f)) {
      ++c.corpus_queries;
      cert.check_query(q);
    }
  }
}

// per_family queries of every family, family j from stream j.
void check_families(Certificate& c, Certifier& cert) {
  const long total = long(all_families().size()) * c.options.per_family;
  std::uint64_t stream = 0;
  for (const Family& f : all_families()) {
    (f.moving ? c.moving_families : c.families).push_back(f.name);
    ++stream;
    for (long i = 0; i < c.options.per_family; ++i, ++c.fuzzed_queries) {
      if (i % 100 == 0) tell(c, "generator families", c.fuzzed_queries, total);
      cert.check_query(generate(f, case_seed(c.options.seed * 1000 + stream, i)).query);
    }
  }
}

void check_soups(Certificate& c, Certifier& cert) {
  const std::uint64_t s = c.options.seed * 1000 + 999;
  for (long i = 0; i < c.options.soups; ++i) {
    tell(c, "tree soups", i, c.options.soups);
    cert.check_soups(generate_soup(24, case_seed(s, 2 * i)),
                     generate_soup(24, case_seed(s, 2 * i + 1)));
  }
}

void check_extra_files(Certificate& c, Certifier& cert) {
  long done = 0;
  for (const std::string& f : c.options.extra_files) {
    tell(c, "extra files", done++, long(c.options.extra_files.size()));
    for (const Query& q : read_query_file(f)) {
      ++c.extra_queries;
      cert.check_query(q);
    }
  }
}

}  // namespace

Certificate certify(const CertifyOptions& options) {
  Certificate c;
  c.options = options;
  if (c.options.per_family < 0) c.options.per_family = options.quick ? 200 : 3000;
  if (c.options.soups < 0) c.options.soups = options.quick ? 30 : 300;
  if (c.options.scene_frames < 0) c.options.scene_frames = options.quick ? 600 : 100000000;
  if (c.options.scene_stride < 1) c.options.scene_stride = options.quick ? 50 : 10;
  c.commit = build_commit();
  c.cgal = exact::cgal_library_version();
  c.gmp = exact::gmp_library_version();
  Certifier cert(c);
  check_corpus(c, cert);
  check_families(c, cert);
  check_scenes(c, cert);
  check_soups(c, cert);
  check_extra_files(c, cert);
  tell(c, "peers", 0, 0);
  c.peers = certify_peers(peer_options(c.options));
  if (c.first_violation.empty()) c.first_violation = c.peers.first_own_violation;
  return c;
}

}  // namespace fdh::verify

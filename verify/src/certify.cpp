#include "fdh/verify/certify.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "fdh/bvh.hpp"
#include "fdh/ccd/robust.hpp"
#include "fdh/cloth/simulation.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/exact/kdop.hpp"
#include "fdh/exact/point_triangle.hpp"
#include "fdh/exact/versions.hpp"
#include "fdh/point_triangle/robust.hpp"
#include "fdh/verify/atomic_file.hpp"
#include "fdh/verify/case_files.hpp"
#include "fdh/verify/families.hpp"
#include "fdh/verify/fuzz.hpp"
#include "fdh/verify/json.hpp"
#include "fdh/verify/moving_families.hpp"
#include "fdh/verify/query_io.hpp"
#include "fdh/verify/scene_file.hpp"
#include "fdh/verify/scene_run.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;
namespace {

std::string git_commit() {
  std::string out;
  if (std::FILE* p = ::popen("git rev-parse --short=12 HEAD 2>/dev/null", "r")) {
    char buf[64];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "unknown" : out;
}

class Certifier {
 public:
  explicit Certifier(Certificate& c) : c_(c) { fs::create_directories(c.options.out_dir); }

  void check_query(const Query& q) {
    const std::vector<Vec3> all(q.x.begin(), q.x.end());
    check_boxes(q, all);
    if (!q.is_static_vf()) return check_moving(q);
    check_boxes(q, {q.b0(), q.b1()});
    check_boxes(q, {q.d(), q.e(), q.f()});
    ++c_.static_queries;
    const Filtered f = robust_point_triangle_filter(q.b0(), q.b1(), q.d(), q.e(), q.f());
    c_.filter_decided += f != Filtered::Uncertain;
    const bool exact = exact::point_triangle_hit(q.b0(), q.b1(), q.d(), q.e(), q.f());
    check_truth(q, exact);
    const bool robust =
        robust_point_triangle(q.b0(), q.b1(), q.d(), q.e(), q.f(), &exact::point_triangle_hit);
    if (robust != exact) {
      ++c_.robust_violations;
      Query saved = q;
      saved.truth = exact;
      violation(saved, "robust says " + std::string(robust ? "hit" : "no") + ", exact says " +
                           (exact ? "hit" : "no"));
    }
  }

  // A moving query: robust CCD against exact CCD, and exact against a stored truth.
  void check_moving(const Query& q) {
    ++c_.moving_queries;
    c_.moving_filter_decided += robust_ccd_filter(q) != Filtered::Uncertain;
    const bool exact = exact::ccd_hit(q);
    check_truth(q, exact);
    const bool robust = robust_ccd(q, &exact::ccd_hit);
    if (robust != exact) {
      ++c_.moving_violations;
      Query saved = q;
      saved.truth = exact;
      violation(saved, "robust CCD says " + std::string(robust ? "hit" : "no") +
                           ", exact CCD says " + (exact ? "hit" : "no"));
    }
  }

  void check_truth(const Query& q, bool exact) {
    if (!q.has_truth()) return;
    ++c_.truths;
    if (exact != bool(q.truth)) {
      ++c_.truth_violations;
      violation(q, "exact says " + std::string(exact ? "hit" : "no") + ", the stored truth says " +
                       (q.truth ? "hit" : "no"));
    }
  }

  void check_soups(const Soup& a, const Soup& b) {
    for (std::size_t i = 0; i < kCertifiedK.size(); ++i) {
      with_k(kCertifiedK[i], [&](auto kc) {
        constexpr int K = decltype(kc)::value;
        const Bvh<K> ta(a.tris, a.x0, a.x1), tb(b.tris, b.x0);
        std::vector<std::pair<int, int>> found;
        traverse(ta, tb, found);
        const std::set<std::pair<int, int>> got(found.begin(), found.end());
        const auto pairs = exact::overlapping_pairs(K, primitive_corners(a.tris, a.x0, a.x1),
                                                    primitive_corners(b.tris, b.x0, {}));
        ++c_.soup_pairs[i];
        c_.exact_pairs[i] += long(pairs.size());
        for (const auto& p : pairs)
          if (!got.count(p)) {
            ++c_.cull_violations[i];
            soup_violation(a, b, K, p);
            break;
          }
      });
    }
  }

 private:
  template <int K>
  void check_boxes_k(const Query& q, const std::vector<Vec3>& pts, std::size_t i) {
    const Kdop<K> box = kdop_of<K>(pts.data(), pts.size());
    ++c_.boxes[i];
    const int s =
        exact::first_uncontained_slab(K, pts.data(), pts.size(), box.lo.data(), box.hi.data());
    if (s >= 0) {
      ++c_.box_violations[i];
      violation(q, "the float " + std::to_string(K) + "-DOP of " + std::to_string(pts.size()) +
                       " of its points misses the exact extent in slab " + std::to_string(s));
    }
  }

  void check_boxes(const Query& q, const std::vector<Vec3>& pts) {
    for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
      with_k(kCertifiedK[i], [&](auto kc) { check_boxes_k<decltype(kc)::value>(q, pts, i); });
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
};

// Every shipped scene runs with robust as its narrow phase (and its self-collision pass, if it
// has one); the narrow-phase queries of every stride-th frame are certified like any other.
void check_scenes(Certificate& c, Certifier& cert) {
  const fs::path dir = fs::path(c.options.corpus_dir) / "scenes";
  if (!fs::is_directory(dir)) return;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".scene") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  const int stride = c.options.scene_stride;
  for (const fs::path& file : files) {
    const cloth::Scene scene = read_scene(file.string());
    SceneRunOptions opt;  // robust, k = 18, the scene's step as `simulate` takes it
    opt.frames = int(std::min<long>(scene.frames, c.options.scene_frames));
    opt.check = false;  // certified here instead
    opt.on_frame = [&](const cloth::Simulation& sim, int f) {
      if (f % stride) return;
      for (const auto& nq : sim.queries()) {
        Query q = sim.query(nq);
        q.id = scene.name + "/f" + std::to_string(f) + "p" + std::to_string(nq.particle) + "t" +
               std::to_string(nq.triangle);
        q.file = file.string();
        ++c.scene_queries;
        cert.check_query(q);
      }
    };
    ++c.scenes;
    run_scene(scene, opt);
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
  c.commit = git_commit();
  c.cgal = exact::cgal_library_version();
  c.gmp = exact::gmp_library_version();
  Certifier cert(c);

  for (const std::string& f : list_query_files(options.corpus_dir)) {
    ++c.corpus_files;
    for (const Query& q : read_native(f)) {
      ++c.corpus_queries;
      cert.check_query(q);
    }
  }
  std::uint64_t stream = 0;
  for (const Family f : all_families()) {
    c.families.push_back(family_name(f));
    ++stream;
    for (long i = 0; i < c.options.per_family; ++i, ++c.fuzzed_queries)
      cert.check_query(
          gen_family(f)(rc::Random(case_seed(c.options.seed * 1000 + stream, i))).value().query);
  }
  for (const MovingFamily f : all_moving_families()) {
    c.moving_families.push_back(moving_family_name(f));
    ++stream;
    for (long i = 0; i < c.options.per_family; ++i, ++c.fuzzed_queries)
      cert.check_query(
          gen_moving(f)(rc::Random(case_seed(c.options.seed * 1000 + stream, i))).value().query);
  }
  check_scenes(c, cert);
  for (long i = 0; i < c.options.soups; ++i) {
    const std::uint64_t s = c.options.seed * 1000 + 999;
    cert.check_soups(gen_soup(24)(rc::Random(case_seed(s, 2 * i))).value(),
                     gen_soup(24)(rc::Random(case_seed(s, 2 * i + 1))).value());
  }
  for (const std::string& f : options.extra_files)
    for (const Query& q : read_query_file(f)) {
      ++c.extra_queries;
      cert.check_query(q);
    }
  return c;
}

void write_certificate(const Certificate& c) {
  const fs::path dir(c.options.out_dir);
  write_file_atomically((dir / "certificate.json").string(), certificate_json(c));
  write_file_atomically((dir / "certificate.md").string(), certificate_markdown(c));
}

std::string certificate_json(const Certificate& c) {
  std::ostringstream os;
  const auto per_k = [&](const char* a, const std::array<long, 4>& x, const char* b,
                         const std::array<long, 4>& y, const char* v,
                         const std::array<long, 4>& z) {
    os << "{";
    for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
      os << (i ? ", " : "") << '"' << kCertifiedK[i] << "\": {\"" << a << "\": " << x[i]
         << (b ? std::string(", \"") + b + "\": " + std::to_string(y[i]) : std::string()) << ", \""
         << v << "\": " << z[i] << "}";
    os << "}";
  };
  os << "{\"certified\": " << (c.certified() ? "true" : "false") << ", \"commit\": \"" << c.commit
     << "\", \"cgal\": \"" << c.cgal << "\", \"gmp\": \"" << c.gmp << "\", \"mode\": \""
     << (c.options.quick ? "quick" : "full") << "\", \"seed\": " << c.options.seed
     << ",\n \"inputs\": {\"corpus_files\": " << c.corpus_files
     << ", \"corpus_queries\": " << c.corpus_queries
     << ", \"fuzzed_per_family\": " << c.options.per_family
     << ", \"families\": " << c.families.size() << ", \"fuzzed_queries\": " << c.fuzzed_queries
     << ", \"soup_pairs\": " << c.options.soups
     << ", \"moving_families\": " << c.moving_families.size() << ", \"scenes\": " << c.scenes
     << ", \"scene_queries\": " << c.scene_queries
     << ", \"extra_files\": " << c.options.extra_files.size()
     << ", \"extra_queries\": " << c.extra_queries << "},\n \"kdop_contains_exact\": ";
  per_k("boxes", c.boxes, nullptr, c.boxes, "violations", c.box_violations);
  os << ",\n \"tree_no_false_cull\": ";
  per_k("soup_pairs", c.soup_pairs, "exact_overlapping_pairs", c.exact_pairs, "violations",
        c.cull_violations);
  os << ",\n \"robust_equals_exact\": {\"static_queries\": " << c.static_queries
     << ", \"decided_by_filter\": " << c.filter_decided
     << ", \"violations\": " << c.robust_violations
     << "},\n \"robust_ccd_equals_exact_ccd\": {\"moving_queries\": " << c.moving_queries
     << ", \"decided_by_filter\": " << c.moving_filter_decided
     << ", \"violations\": " << c.moving_violations
     << "},\n \"exact_equals_stored_truth\": {\"queries\": " << c.truths
     << ", \"violations\": " << c.truth_violations
     << "},\n \"first_violation\": " << json_string(c.first_violation) << "}\n";
  return os.str();
}

std::string certificate_markdown(const Certificate& c) {
  std::ostringstream os;
  os << "# fdhcert certificate\n\n"
     << (c.certified() ? "**Certified**: no violation.\n"
                       : "**Violated**: " + c.first_violation + ".\n")
     << "\nCommit `" << c.commit << "`, CGAL " << c.cgal << ", GMP " << c.gmp << ", "
     << (c.options.quick ? "quick" : "full") << " run, seed " << c.options.seed
     << ". Made by `fdhcert certify" << (c.options.quick ? " --quick" : "") << "`.\n\n"
     << "## Inputs\n\n| source | queries |\n|---|---|\n"
     << "| corpus (`" << c.options.corpus_dir << "`, " << c.corpus_files << " files) | "
     << c.corpus_queries << " |\n"
     << "| fuzzed: " << c.options.per_family << " per family, " << c.families.size()
     << " static and " << c.moving_families.size() << " moving families | " << c.fuzzed_queries
     << " |\n"
     << "| extra files (" << c.options.extra_files.size() << ") | " << c.extra_queries << " |\n"
     << "| narrow-phase queries recorded from the shipped scenes (" << c.scenes
     << " scenes, robust, every " << c.options.scene_stride << "th frame) | " << c.scene_queries
     << " |\n"
     << "| random triangle-soup pairs (tree) | " << c.options.soups << " |\n\n"
     << "## Properties\n\n| property | k | checked | violations |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
    os << "| float FDH contains the exact FDH | " << kCertifiedK[i] << " | " << c.boxes[i]
       << " boxes | " << c.box_violations[i] << " |\n";
  for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
    os << "| tree traversal finds every exactly overlapping pair | " << kCertifiedK[i] << " | "
       << c.soup_pairs[i] << " tree pairs, " << c.exact_pairs[i]
       << " overlapping primitive pairs | " << c.cull_violations[i] << " |\n";
  os << "| `robust` = `exact`, static vertex-face | – | " << c.static_queries << " queries ("
     << c.filter_decided << " decided by the float filter alone) | " << c.robust_violations
     << " |\n"
     << "| `robust` = `exact`, moving vertex-face and edge-edge (CCD) | – | " << c.moving_queries
     << " queries (" << c.moving_filter_decided << " decided by the float filter alone) | "
     << c.moving_violations << " |\n"
     << "| `exact` = the known truth (corpus and benchmark files; fuzzed queries whose "
        "construction fixes it) | – | "
     << c.truths << " queries | " << c.truth_violations << " |\n";
  return os.str();
}

}  // namespace fdh::verify

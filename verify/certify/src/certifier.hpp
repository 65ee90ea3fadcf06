// The certifier: every promised method against the exact twin on each query, soup and box it is
// given, and the tally of what that adds to the certificate. Private to fdh_certify: certify.cpp
// feeds it the run's inputs stage by stage.
#pragma once

#include "fdh/certify/certify.hpp"

#include <fmt/format.h>

#include <algorithm>
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

#include "certify_tally.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

// Every method with a promise, on every query decision it makes and every box it builds, against
// the exact twin through the checker (check/checker.hpp). The checks are const: each writes into
// the CertifyTally it is given, so queries are checked on every core (check_queries) and the
// CertifyTally merged into the certificate (record) in input order.
class Certifier {
 public:
  // With `delta`, the minimum-separation stage's (Certificate::delta): only the methods that
  // answer δ > 0, no boxes (they do not depend on δ).
  explicit Certifier(Certificate& c, bool delta = false)
      : c_(c),
        delta_(delta),
        methods_(stage_methods(promised_methods(), delta)),
        timed_(stage_methods(time_promised_methods(), delta)),
        boxes_(delta ? std::vector<BoxMethod>() : all_box_methods()),
        metamorphic_(c.options.runs("metamorphic") ? stage_methods(all_methods(), delta)
                                                   : std::vector<Method>()) {
    fs::create_directories(c.options.files_dir());
    for (const Method& m : methods_)
      for (const Decision d : kQueryDecisions)
        if (m.test[std::size_t(d)]) zero_.promises.push_back({m.name, d, m.promise});
    for (const Method& m : timed_)
      for (const Decision d : kToiDecisions)
        if (m.toi[toi_index(d)]) zero_.times.push_back({m.name, d, m.time_promise, {}, {}});
    for (const BoxMethod& b : boxes_) {
      zero_.boxes.push_back({b.name, b.k});
      zero_.boxes.back().tree = b.builds_tree;
    }
    zero_.metamorphic = metamorphic_.rows();
    zero_.transforms = transform_counts();
    total_ = zero_;
    write_counts();
  }

  // Every query of qs, on every core; the certificate then counts them in order. Returns the
  // queries checked (fewer once the budget is spent).
  long check_queries(const std::vector<QueryRecord>& qs) {
    const CertifyTally t = tally(qs);
    record(t);
    return t.queries;
  }

  // What qs adds to the certificate: checked on every core, merged in order. Safe to call from
  // several threads at once.
  CertifyTally tally(const std::vector<QueryRecord>& qs) const {
    const auto check_chunk = [&](std::size_t begin, std::size_t end, CertifyTally& t) {
      for (std::size_t i = begin; i < end; ++i) check_query(qs[i], t);
    };
    CertifyTally sum = zero_;
    for (const CertifyTally& t : parts_in_order(qs.size(), 16, zero_, check_chunk)) sum.add(t);
    sum.queries = long(qs.size()) - sum.skipped;
    return sum;
  }

  const CertifyTally& zero() const { return zero_; }

  // Soup pairs (a[i], b[i]), as check_queries.
  void check_soups(const std::vector<Soup>& a, const std::vector<Soup>& b) {
    const auto parts = parts_in_order(
        a.size(), 1, zero_,
        [&](std::size_t i, std::size_t, CertifyTally& t) { check_soup_pair(a[i], b[i], t); });
    for (const CertifyTally& t : parts) record(t);
  }

  // t's counts into the certificate; its violation, if the certificate's first, saved.
  void record(const CertifyTally& t) {
    for (const CertifyTally::Found& f : t.found) {
      if (total_.has(f.key)) continue;                              // this kind is saved already
      const fs::path file = fs::path(c_.options.out_dir) / f.file;  // as the user names it
      // A query that breaks two promises is one file, with the first one's words.
      if (written_.insert(f.file).second)
        write_file_atomically((fs::path(c_.options.files_dir()) / f.file).string(), f.text);
      c_.broken_saved.push_back(f.what + ", saved to " + file.string());
      if (c_.first_violation.empty()) c_.first_violation = c_.broken_saved.back();
    }
    total_.add(t);
    write_counts();
  }

 private:
  static std::vector<Method> stage_methods(std::vector<Method> ms, bool delta) {
    if (delta)
      ms.erase(std::remove_if(ms.begin(), ms.end(),
                              [](const Method& m) { return !m.answers_min_distance; }),
               ms.end());
    return ms;
  }

  // The certificate's rows and counts are total_'s.
  void write_counts() {
    if (delta_) {
      DeltaStage& d = c_.delta;
      d.promises = total_.promises, d.times = total_.times, d.metamorphic = total_.metamorphic;
      d.metamorphic_transforms = total_.transforms;
      d.truths = total_.truths, d.truth_violations = total_.truth_violations;
      return;
    }
    c_.promises = total_.promises, c_.boxes = total_.boxes, c_.metamorphic = total_.metamorphic;
    c_.times = total_.times, c_.metamorphic_transforms = total_.transforms;
    c_.truths = total_.truths, c_.truth_violations = total_.truth_violations;
  }

  void check_query(const QueryRecord& r, CertifyTally& t) const {
    if (budget().spent()) {
      ++t.skipped;
      return;
    }
    const RecordScope asking(r);  // a plug-in's crash names r
    const Query& q = r.query;
    check_boxes(r, std::vector<Vec3>(q.x.begin(), q.x.end()), t);
    if (q.is_static_vf() && !delta_) {
      check_boxes(r, {q.b0(), q.b1()}, t);
      check_boxes(r, {q.d(), q.e(), q.f()}, t);
    }
    const bool twin = twin_hit(q);
    check_truth(r, twin, t);
    // The query as drawn first: where it already breaks a promise, that is the case saved, and
    // its verdicts are not asked again under the transforms.
    MetamorphicCertifier::Said said;
    std::set<std::string> broke;  // methods that broke a promise on q as drawn
    check_verdicts(r, twin, t, said, broke);
    check_times(r, twin, t, broke);
    if (const auto broken =
            metamorphic_.check(q, twin, t.metamorphic, t.transforms, budget(), said)) {
      QueryRecord saved = with_truth(r, twin);  // the truth, id and place of q: the transform's
      saved.query = broken->saved;
      if (!broke.count(broken->method))
        violation(saved, broken->method + "/metamorphic", broken->what, t,
                  broken->before(with_truth(r, twin)));
    }
  }

  // Each promised method's verdict on q against the twin; `said` gets the verdicts (nullopt: no
  // answer in time), `broke` the methods that broke their promise.
  void check_verdicts(const QueryRecord& r, bool twin, CertifyTally& t,
                      MetamorphicCertifier::Said& said, std::set<std::string>& broke) const {
    const Query& q = r.query;
    const Decision d = decision_of(q);
    for (std::size_t i = 0; i < t.promises.size(); ++i) {
      PromiseCheck& p = t.promises[i];
      if (p.decision != d) continue;
      const Method& m = method(p.method);
      if (!m.applies_to(q)) continue;  // a plug-in that answers contact only, at δ > 0
      const auto& filter = m.filter[std::size_t(d)];
      p.filter_decided += filter && filter(q) != Filtered::Uncertain;
      ++p.checked;
      Verdicts v;
      try {
        v = check(m, q, twin);
      } catch (const NoAnswer& e) {  // abandoned: a broken promise on q, and the run goes on
        v = unanswered(m, e, twin);
      }
      said[m.name] = v.no_answer ? std::nullopt : std::optional<bool>(v.said);
      if (v.kept) continue;
      ++p.violations;
      p.no_answer += v.no_answer;
      broke.insert(m.name);
      violation(with_truth(r, twin),
                m.name + "/" + to_string(d) + (v.no_answer ? "/no-answer" : "/verdict"),
                describe(m, v) + " (" + to_string(d) + ")", t);
    }
  }

  // Each time-promised method's time of impact against the exact earliest contact.
  void check_times(const QueryRecord& r, bool twin, CertifyTally& t,
                   std::set<std::string>& broke) const {
    if (t.times.empty()) return;
    const Query& q = r.query;
    const Decision d = toi_decision_of(q);
    const TimeTwin exact = time_twin(q);
    for (TimePromiseCheck& row : t.times) {
      if (row.decision != d) continue;
      const Method& m = named(timed_, row.method);
      if (q.min_distance > 0 && !m.answers_min_distance) continue;
      TimeCheck c;
      try {
        c = check_time(m, q, c_.options.toi_width, exact);
      } catch (const NoAnswer& e) {
        c = unanswered_time(m, e, c_.options.toi_width, exact);
      }
      row.tally.add(c, 0, 0);
      if (c.zero && row.zero_queries.size() < kZeroNamed)
        row.zero_queries.push_back(r.file.empty() ? "'" + r.id + "'"
                                                  : r.file + ":" + std::to_string(r.line));
      if (c.kept) continue;
      broke.insert(m.name);
      const char* kind = c.no_answer ? "/no-answer" : c.garbage ? "/not-a-time" : "/time";
      violation(with_truth(r, twin), m.name + "/" + to_string(d) + kind,
                judged_time_words(m, c) + " (" + to_string(d) + ")", t);
    }
  }

  static QueryRecord with_truth(QueryRecord r, bool twin) {
    r.truth = truth_of(twin);
    return r;
  }

  void check_truth(const QueryRecord& q, bool twin, CertifyTally& t) const {
    const std::optional<bool> agrees = twin_matches_truth(stated(q.truth), twin);
    if (!agrees) return;
    ++t.truths;
    if (*agrees) return;
    ++t.truth_violations;
    violation(q, "truth",
              "exact says " + std::string(twin ? "hit" : "no") + ", the stored truth says " +
                  (q.truth == Truth::Yes ? "hit" : "no"),
              t);
  }

  // The FDH tree of each certified k culls no pair whose exact k-DOPs overlap.
  void check_soup_pair(const Soup& a, const Soup& b, CertifyTally& t) const {
    for (BoxCheck& box : t.boxes) {
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
        soup_violation(a, b, K, culled.front(), t);
      });
    }
  }

  const Budget& budget() const { return c_.options.budget; }

  static const Method& named(const std::vector<Method>& ms, const std::string& name) {
    return *std::find_if(ms.begin(), ms.end(), [&](const Method& m) { return m.name == name; });
  }
  const Method& method(const std::string& name) const { return named(methods_, name); }

  void check_boxes(const QueryRecord& q, const std::vector<Vec3>& pts, CertifyTally& t) const {
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      BoxCheck& box = t.boxes[i];
      ++box.boxes;
      int s = -1;
      try {
        s = check_box(boxes_[i], pts.data(), pts.size());
      } catch (const NoAnswer& e) {
        ++box.box_violations;
        violation(q, box.method + "/" + std::to_string(box.k) + "/no-answer",
                  box.method + " gives no " + std::to_string(box.k) + "-DOP of " +
                      std::to_string(pts.size()) + " of its points in " +
                      fmt::format("{:g}", e.seconds) + " s",
                  t);
        continue;
      }
      if (s < 0) continue;
      ++box.box_violations;
      violation(q, box.method + "/" + std::to_string(box.k) + "/box",
                "the " + box.method + " " + std::to_string(box.k) + "-DOP of " +
                    std::to_string(pts.size()) + " of its points misses the exact extent in slab " +
                    std::to_string(s),
                t);
    }
  }

  // The first violation of its kind (`key`) in t is kept; `note`, if not empty, is a second
  // comment in the saved case.
  static void violation(const QueryRecord& q, const std::string& key, const std::string& what,
                        CertifyTally& t, const std::string& note = "") {
    if (t.has(key)) return;
    std::vector<std::string> comments = {"certify: " + what + "."};
    if (!note.empty()) comments.push_back(note);
    t.keep(CertifyTally::Found{
        key,
        what + " (query " + q.id + " from " +
            (q.file.empty() ? "a generator" : q.file + ":" + std::to_string(q.line)) + ")",
        "violation-" + case_hash(q.query) + ".vf", case_file_text(q, comments)});
  }

  // A missed pair is saved as an OBJ: A at t = 0, A at t = 1 (its swept leaves), and B.
  static void soup_violation(const Soup& a, const Soup& b, int k, std::pair<int, int> p,
                             CertifyTally& t) {
    if (t.has("tree")) return;
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
      for (const Tri& tri : tris)
        os << "f " << tri[0] + base << ' ' << tri[1] + base << ' ' << tri[2] + base << "\n";
      base += int(x.size());
    };
    object("A_t0", a.x0, a.tris);
    object("A_t1", a.x1, a.tris);
    object("B", b.x0, b.tris);
    t.keep(CertifyTally::Found{"tree", "the " + std::to_string(k) + "-DOP tree missed a pair",
                               "violation-tree.obj", os.str()});
  }

  Certificate& c_;
  const bool delta_;
  const std::vector<Method> methods_;
  const std::vector<Method> timed_;
  const std::vector<BoxMethod> boxes_;
  const MetamorphicCertifier metamorphic_;
  CertifyTally zero_;              // every row, every count 0
  CertifyTally total_;             // what record() has merged so far
  std::set<std::string> written_;  // the case files written, by name
};

}  // namespace fdh::verify

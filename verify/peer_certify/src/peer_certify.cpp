#include "fdh/peer_certify/peer_certify.hpp"

#include <algorithm>
#include <filesystem>

#include "fdh/check/checker.hpp"
#include "fdh/check/parallel.hpp"
#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/point_sets.hpp"
#include "fdh/gen/shrink_point_sets.hpp"
#include "fdh/io/peer_case_file.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/build_info.hpp"
#include "fdh/peers/peers.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;
namespace {

bool is_overlap(const PeerCase& c) {
  return c.property == "overlap";
}

// What one method did on one case, through the checker, held to the conservative promise
// whatever the method itself promises: whether it fails the property, and (overlap) whether
// the exact FDHs overlap.
struct Outcome {
  bool fails = false, exact_overlap = false;
};

Outcome outcome(const BoxMethod& m, const PeerCase& c) {
  if (!is_overlap(c)) return {check_box(m, c.a.data(), c.a.size()) >= 0, false};
  const Verdicts v = check_overlap(m, c.a, c.b);
  return {!keeps_promise(Promise::Conservative, v.said, v.twin), v.twin};
}

// A row and the method it certifies.
struct Entry {
  PeerRow row;
  BoxMethod method;
};

Entry entry(const std::string& library, const std::string& version, const std::string& precision,
            std::string method, const BoxMethod& m) {
  PeerRow row;
  row.library = library, row.version = version, row.precision = precision;
  row.method = std::move(method), row.summary = m.summary;
  row.k = m.k, row.promise = m.promise;
  return {row, m};
}

// The registry's k-DOPs (the project's own, "fdh-18", and any plug-in's, library "plug-in":
// held to their promise like ours), then each peer library's methods.
std::vector<Entry> entries() {
  std::vector<Entry> out;
  for (const BoxMethod& m : all_box_methods())
    out.push_back(entry(m.builds_tree ? "fdhcert" : "plug-in", build_commit(), "double",
                        m.name + "-" + std::to_string(m.k), m));
  for (const PeerLibrary& lib : all_peer_libraries())
    for (const BoxMethod& m : lib.methods)
      out.push_back(entry(lib.name, lib.version, lib.precision, m.name, m));
  return out;
}

// A generated case and where it came from, for the saved file.
struct Drawn {
  PeerCase c;
  std::string origin;
};

class PeerRun {
 public:
  explicit PeerRun(PeersReport& r) : r_(r) {}

  // Every method on every case: the outcomes on every core (check/parallel.hpp), then counted,
  // shrunk and saved on this thread in the cases' order.
  void check(std::vector<Drawn> cases) {
    std::vector<std::vector<Outcome>> outcomes(cases.size());
    for_each_index(cases.size(), 8, [&](std::size_t i) {
      for (const Entry& e : entries_) outcomes[i].push_back(outcome(e.method, cases[i].c));
    });
    for (std::size_t i = 0; i < cases.size(); ++i)
      for (std::size_t e = 0; e < entries_.size(); ++e)
        count(entries_[e], cases[i], outcomes[i][e]);
  }

  void replay(const PeerCase& c, const std::string& file) {
    for (Entry& e : entries_) {
      const bool own = e.row.promise != Promise::None;
      if (!own && (e.row.library != c.library || e.row.method != c.method)) continue;
      PeerProperty& p = is_overlap(c) ? e.row.overlap : e.row.containment;
      ++p.stored;
      if (!outcome(e.method, c).fails) continue;
      ++p.stored_failing;
      if (own) own_violation(e, "on the stored case " + file);
    }
  }

  void finish() {
    for (Entry& e : entries_) r_.rows.push_back(std::move(e.row));
  }

 private:
  void count(Entry& e, Drawn& d, Outcome o) {
    PeerCase& c = d.c;
    PeerProperty& p = is_overlap(c) ? e.row.overlap : e.row.containment;
    ++p.checked;
    p.exact_overlaps += o.exact_overlap;
    if (!o.fails) return;
    ++p.violations;
    c.library = e.row.library, c.method = e.row.method;
    std::string saved;
    if (int(p.shrunk.size()) < r_.options.keep) saved = save(e, p, shrunk(e.method, c), d.origin);
    if (e.row.promise != Promise::None)
      own_violation(e, "on a " + d.origin + (saved.empty() ? "" : ", saved to " + saved));
  }

  PeerCase shrunk(const BoxMethod& m, PeerCase c) const {
    PointSets sets = {c.a};
    if (is_overlap(c)) sets.push_back(c.b);
    const auto still_fails = [&](const PointSets& s) {
      PeerCase t = c;
      t.a = s[0], t.b = s.size() > 1 ? s[1] : std::vector<Vec3>{};
      return outcome(m, t).fails;
    };
    sets = shrink_point_sets(sets, still_fails, r_.options.quick ? 600 : 3000);
    c.a = sets[0], c.b = sets.size() > 1 ? sets[1] : std::vector<Vec3>{};
    return c;
  }

  // The saved file's path, or "" when cases are not saved.
  std::string save(const Entry& e, PeerProperty& p, const PeerCase& c, const std::string& origin) {
    if (r_.options.save_dir.empty()) return "";
    const PeerOptions& o = r_.options;
    const fs::path dir = fs::path(o.save_dir) / c.library;
    const std::string path = (fs::path(o.saved_name.empty() ? o.save_dir : o.saved_name) /
                              c.library / peer_case_file_name(c))
                                 .string();
    if (std::find(p.shrunk.begin(), p.shrunk.end(), path) != p.shrunk.end()) return path;
    fs::create_directories(dir);
    const std::string what = is_overlap(c)
                                 ? "calls two sets disjoint whose exact FDHs overlap"
                                 : "builds a box that misses the exact FDH of its points in a slab";
    write_file_atomically((dir / peer_case_file_name(c)).string(),
                          peer_case_text(c, {c.library + " " + e.row.version + " " + c.method +
                                                 " (" + e.row.summary + ") " + what + ".",
                                             "Shrunk from a " + origin + "."}));
    p.shrunk.push_back(path);
    return path;
  }

  void own_violation(const Entry& e, const std::string& where) {
    if (r_.first_own_violation.empty())
      r_.first_own_violation = "the project's " + e.row.method + " fails a peers property " + where;
  }

  PeersReport& r_;
  std::vector<Entry> entries_ = entries();
};

}  // namespace

// The sum of two counts of both properties over the own rows.
long PeersReport::own_sum(long PeerProperty::*first, long PeerProperty::*second) const {
  long n = 0;
  for (const PeerRow& row : rows)
    if (row.promise != Promise::None)
      for (const PeerProperty* p : {&row.containment, &row.overlap}) n += p->*first + p->*second;
  return n;
}

long PeersReport::own_checks() const {
  return own_sum(&PeerProperty::checked, &PeerProperty::stored);
}

long PeersReport::own_violations() const {
  return own_sum(&PeerProperty::violations, &PeerProperty::stored_failing);
}

PeersReport certify_peers(const PeerOptions& options) {
  PeersReport r;
  r.options = options;
  if (r.options.cases < 0) r.options.cases = options.quick ? 300 : 20000;
  if (r.options.keep < 0) r.options.keep = options.quick ? 1 : 3;
  PeerRun run(r);
  const std::uint64_t stream = r.options.seed * 1000 + 500;
  const long batch = 1000;  // cases drawn, then checked, at a time
  for (long first = 0; first < r.options.cases; first += batch) {
    report(options.progress, {"peers", first, r.options.cases, "cases"});
    std::vector<Drawn> cases;
    for (long i = first; i < std::min(first + batch, r.options.cases); ++i) {
      const std::string seed =
          "seed " + std::to_string(r.options.seed) + ", case " + std::to_string(i);
      cases.push_back({{"", "", "containment", random_point_set(case_seed(stream, i)), {}},
                       "random point set (" + seed + ")"});
      TouchingSets t = touching_point_sets(case_seed(stream + 1, i));
      cases.push_back({{"", "", "overlap", std::move(t.a), std::move(t.b)},
                       "pair of sets touching at a " + t.contact + " (" + seed + ")"});
    }
    run.check(std::move(cases));
  }
  if (!r.options.replay_dir.empty())
    for (const std::string& f : list_peer_case_files(r.options.replay_dir))
      run.replay(read_peer_case(f), f);
  run.finish();
  return r;
}

}  // namespace fdh::verify

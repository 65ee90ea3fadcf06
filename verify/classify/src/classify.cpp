#include "fdh/classify/classify.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "fdh/classify/classification_output.hpp"
#include "fdh/classify/toi_report.hpp"
#include "fdh/io/json_text.hpp"
#include "fdh/io/record_scope.hpp"
#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {
namespace {

using Json = nlohmann::ordered_json;

// How many of a method's allowed disagreements (a conservative method's false alarms) classify
// names one by one; the rest are counted in one line (and in the table's FP).
constexpr std::size_t kAllowedNamed = 10;

bool promised(const Method& m) {
  return !m.is_twin && m.promise != Promise::None;
}

const Method* named(const std::vector<Method>& methods, const std::string& name) {
  for (const Method& m : methods)
    if (m.name == name) return &m;
  return nullptr;
}

// The times a verdict pass kept, by query (its bytes: kind, points, δ), for the time pass.
using KeptTimes = std::shared_ptr<std::map<std::string, Toi>>;
std::string key_of(const Query& q) {
  std::string k(reinterpret_cast<const char*>(q.x.data()), sizeof(Vec3) * q.x.size());
  k.append(reinterpret_cast<const char*>(&q.min_distance), sizeof q.min_distance);
  return k + char(q.kind);
}

// With --toi, a method whose time gives its verdict (Method::verdict_from_toi) is called once
// per query: its verdict pass calls the time function and keeps the time; its time pass reads
// it back (and reports the verdict pass's ns per query, the calls' own time).
std::pair<Method, Method> once_per_query(const Method& m, double width) {
  const KeptTimes kept = std::make_shared<std::map<std::string, Toi>>();
  Method verdict = m, time = m;
  for (const Decision d : kQueryDecisions)
    if (const QueryToi& toi = m.toi[d == Decision::EdgeEdgeCcd ? 1 : 0];
        toi && m.test[std::size_t(d)])
      verdict.test[std::size_t(d)] = [toi, width, kept](const Query& q) {
        const Toi t = toi(q, width);
        kept->emplace(key_of(q), t);
        return t.hit;
      };
  for (QueryToi& toi : time.toi)
    if (toi)
      toi = [toi, kept](const Query& q, double w) {
        const auto found = kept->find(key_of(q));
        return found != kept->end() ? found->second : toi(q, w);
      };
  return {verdict, time};
}

// The verdict pass's ns per query as the time pass's, for the methods asked once per query.
void once_per_query_times(const std::vector<Method>& methods, const ClassifiedFiles& c,
                          ToiClassifiedFiles& toi) {
  const auto copy = [&](const Classification& v, ToiClassification& t) {
    for (ToiResult& r : t.methods)
      for (const MethodResult& m : v.methods) {
        const Method* asked = named(methods, m.name);
        if (m.name == r.name && asked && asked->verdict_from_toi)
          r.ns_per_query = m.tally.ns_per_query;
      }
  };
  copy(c.total, toi.total);
  for (std::size_t i = 0; i < c.files.size() && i < toi.files.size(); ++i)
    copy(c.files[i].c, toi.files[i].second);
}

// With --toi, --time times each method's time of impact too, as a method of its own named
// "NAME/toi": its "verdict" on a query is the time function's contact.
std::vector<Method> toi_as_methods(const std::vector<Method>& selected, double width) {
  std::vector<Method> out;
  for (const Method& m : selected) {
    if (!m.toi[0] && !m.toi[1]) continue;
    Method t;
    t.name = m.name + "/toi";
    t.answers_min_distance = m.answers_min_distance;
    for (const Decision d : kQueryDecisions)
      if (const QueryToi& toi = m.toi[d == Decision::EdgeEdgeCcd ? 1 : 0])
        t.test[std::size_t(d)] = [toi, width](const Query& q) { return toi(q, width).hit; };
    out.push_back(std::move(t));
  }
  return out;
}

QueryTimings time_queries(const ClassifyOptions& o, const std::vector<QueryRecord>& records,
                          const std::vector<Method>& selected) {
  const std::vector<Query> qs = queries_of(records);
  const RecordScope asking(records, qs);  // a plug-in's crash names FILE:LINE
  QueryTimings t;
  t.methods = selected;
  std::size_t base = selected.size();
  for (std::size_t m = 0; m < selected.size(); ++m)
    if (selected[m].name == o.time_ratio) base = m;
  if (!o.time_ratio.empty() && base == selected.size())
    t.methods.push_back(select_methods({o.time_ratio}, o.gate).front());
  t.ns = time_each_query(qs, t.methods, o.rounds);
  // --time: the selected methods only; --time-ratio's base may have been added after them.
  if (o.time)
    t.spreads = time_spreads(std::vector<std::vector<double>>(
                                 t.ns.begin(), t.ns.begin() + std::ptrdiff_t(selected.size())),
                             selected);
  if (o.time && o.toi) {
    const std::vector<Method> tois = toi_as_methods(selected, o.width);
    const std::vector<TimeSpread> more = time_spreads(time_each_query(qs, tois, o.rounds), tois);
    t.spreads.insert(t.spreads.end(), more.begin(), more.end());
  }
  if (o.time_ratio.empty()) return t;
  for (const std::vector<double>& times : t.ns) {  // each method's mean, each query timed alone
    double sum = 0;
    std::size_t n = 0;
    for (const double x : times) sum += x, n += x > 0;
    t.mean_ns.push_back(n ? sum / double(n) : 0);
  }
  t.ratios = time_ratios(qs, t.ns, t.methods, base, o.ratio_limit);
  return t;
}

Json time_ratio_json(const ClassifyResult& r) {
  const ClassifyOptions& o = r.options;
  const QueryTimings& t = *r.timings;
  Json j{{"to", o.time_ratio}, {"limit", o.ratio_limit}, {"queries", r.classified.all.size()}};
  j["methods"] = Json::object();
  j["mean_ns"] = Json::object();
  for (std::size_t m = 0; m < t.methods.size(); ++m) j["mean_ns"][t.methods[m].name] = t.mean_ns[m];
  for (const TimeRatio& x : t.ratios) {
    if (x.method == o.time_ratio) continue;
    j["methods"][x.method][to_string(x.decision)] = {
        {"queries", x.queries},
        {"max", x.max},
        {"median", x.median},
        {"worst", place_of(r.classified.all[x.worst], Place::LineAndId)},
        {"over_limit", x.over}};
  }
  return j;
}

void print_time_ratios(const ClassifyResult& r, std::ostream& out) {
  const ClassifyOptions& o = r.options;
  const QueryTimings& t = *r.timings;
  for (std::size_t m = 0; m < t.methods.size(); ++m)
    out << fmt::format("{}: {:.1f} ns per query, the mean of each query timed alone\n",
                       t.methods[m].name, t.mean_ns[m]);
  for (const TimeRatio& x : t.ratios) {
    if (x.method == o.time_ratio) continue;
    out << fmt::format(
        "{} / {} time per {} query ({}): max {:.3f} at {}, median {:.3f}, {} above {}\n", x.method,
        o.time_ratio, to_string(x.decision), x.queries, x.max,
        place_of(r.classified.all[x.worst], Place::LineAndId), x.median, x.over, o.ratio_limit);
  }
}

// A method's findings on standard error: every broken promise, the first kAllowedNamed allowed
// disagreements, and how many more were allowed.
void print_method_findings(const ClassifyResult& r, const Method& m, std::ostream& err) {
  std::size_t allowed = 0;
  for (const Finding& f : r.findings) {
    if (f.truth || f.method != m.name || f.judgement == Judgement::Unpromised) continue;
    const bool named = f.judgement == Judgement::Broken || allowed < kAllowedNamed;
    allowed += f.judgement == Judgement::Allowed;
    if (named) err << "fdhcert: " << f.words << "\n";
  }
  if (allowed > kAllowedNamed)
    err << "fdhcert: " << m.name << ": " << allowed - kAllowedNamed
        << " more disagreements with exact " << judgement_words(Judgement::Allowed, m.promise)
        << ", counted in the table\n";
}

}  // namespace

void ClassifyOptions::validate() const {
  const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (files.empty()) bad("classify needs at least one file");
  const std::vector<std::string> kinds = {"", "vertex-face", "edge-edge"};
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
    bad("kind must be 'vertex-face' or 'edge-edge', not '" + kind + "'");
  if (methods.empty())
    all_methods(gate);  // the gate
  else
    select_methods(methods, gate);  // the names and the gate
  if (!time_ratio.empty()) select_methods({time_ratio}, gate);
  if (!(width >= 0x1p-52 && width <= 1)) bad("width must be in [2^-52, 1]");
  if (rounds < 1 || rounds > 100) bad("rounds must be 1 to 100");
  if (!(ratio_limit >= 1e-3 && ratio_limit <= 1e3)) bad("ratio limit must be in [0.001, 1000]");
  if (!std::isfinite(min_distance) || min_distance < 0)
    bad(fmt::format("min distance must be finite and >= 0, not {}", min_distance));
}

ClassifyResult classify_job(const ClassifyOptions& o) {
  o.validate();
  ClassifyResult r;
  r.options = o;
  r.methods = o.methods.empty() ? all_methods(o.gate) : select_methods(o.methods, o.gate);
  std::optional<QueryKind> kind;
  if (!o.kind.empty()) kind = o.kind == "edge-edge" ? QueryKind::EdgeEdge : QueryKind::VertexFace;
  std::vector<Method> verdicts = r.methods, times = r.methods;  // as asked in each pass
  for (std::size_t i = 0; o.toi && i < r.methods.size(); ++i)
    if (r.methods[i].verdict_from_toi)
      std::tie(verdicts[i], times[i]) = once_per_query(r.methods[i], o.width);
  r.classified = classify_files(o.files, verdicts, kind, o.min_distance, o.progress);
  r.findings = findings(r.classified.total, r.classified.all, r.methods, Place::LineAndId);
  if (o.toi) {
    r.toi = classify_toi_files(r.classified, times, o.width, o.progress);
    once_per_query_times(r.methods, r.classified, *r.toi);
    r.time_findings = time_findings(r.toi->total, r.methods);
  }
  if (o.time || !o.time_ratio.empty()) r.timings = time_queries(o, r.classified.all, r.methods);
  return r;
}

std::size_t ClassifyResult::broken() const {
  std::size_t n = 0;
  for (const Finding& f : findings) {
    const Method* m = named(methods, f.method);
    n += f.truth || (m && promised(*m) && f.judgement == Judgement::Broken);
  }
  for (const TimeFinding& f : time_findings) n += !f.check.kept;
  return n;
}

Json ClassifyResult::to_json() const {
  Json j = classification_json(classified.files, classified.total, {options.gate});
  if (options.min_distance > 0) j["min_distance"] = options.min_distance;  // 0: as before δ
  if (toi) j["toi"] = toi_json(toi->files, toi->total);
  if (timings && options.time)
    j["cpu_time"] = cpu_times_json(timings->spreads, classified.all, options.rounds);
  if (timings && !options.time_ratio.empty()) j["time_ratio"] = time_ratio_json(*this);
  return j;
}

std::string ClassifyResult::text() const {
  std::ostringstream out;
  print_table(out, classified.files, classified.total, {options.gate, options.min_distance});
  if (toi) out << "\n", print_toi_table(out, toi->files, toi->total);
  if (timings && options.time)
    out << "\n", print_cpu_times(out, timings->spreads, classified.all, options.rounds);
  if (timings && !options.time_ratio.empty()) {
    if (options.time) out << "\n";
    print_time_ratios(*this, out);
  }
  return out.str();
}

std::string ClassifyResult::findings_text() const {
  std::ostringstream err;
  for (const Finding& f : findings)
    if (f.truth) err << "fdhcert: " << f.words << "\n";
  for (const Method& m : methods)
    if (promised(m)) print_method_findings(*this, m, err);
  if (!toi) return err.str();
  for (const ToiResult& t : toi->total.methods) {
    std::size_t shown = 0;  // the first 16 per method, as the tally keeps them
    for (const TimeFinding& f : time_findings)
      if (f.method == t.name && !f.check.kept && shown++ < 16)
        err << "fdhcert: at " << place_of(classified.all[f.query], Place::LineAndId) << ": "
            << f.words << "\n";
  }
  return err.str();
}

std::string ClassifyResult::per_query_csv() const {
  return fdh::verify::per_query_csv(classified.all, classified.total, toi ? &toi->total : nullptr);
}

void ClassifyResult::write(const std::string& dir) const {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir + "/classify.json", json_text(to_json(), "classify.json"));
  write_file_atomically(dir + "/classify.txt", text());
  write_file_atomically(dir + "/per-query.csv", per_query_csv());
}

}  // namespace fdh::verify

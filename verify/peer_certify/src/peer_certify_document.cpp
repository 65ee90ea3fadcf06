// The peers' results for programs (JSON) and people (Markdown): one row per method and property.
#include <fmt/format.h>

#include <iterator>

#include "fdh/peer_certify/peer_certify.hpp"

namespace fdh::verify {
namespace {

using json = nlohmann::ordered_json;

json property_json(const PeerProperty& p, bool overlap) {
  json j = {{"checked", p.checked}};
  if (overlap) j["exact_overlaps"] = p.exact_overlaps;
  j["violations"] = p.violations;
  j["shrunk"] = p.shrunk;
  j["stored"] = p.stored;
  j["stored_failing"] = p.stored_failing;
  return j;
}

std::string property_cells(const PeerProperty& p, bool overlap) {
  const std::string checked =
      overlap ? fmt::format("{} pairs ({} overlap exactly)", p.checked, p.exact_overlaps)
              : fmt::format("{} point sets", p.checked);
  std::string shrunk;
  for (const std::string& f : p.shrunk) shrunk += (shrunk.empty() ? "`" : ", `") + f + "`";
  return fmt::format("{} | {} | {} | {} of {}", checked, p.violations,
                     shrunk.empty() ? "–" : shrunk, p.stored_failing, p.stored);
}

}  // namespace

json peers_json(const PeersReport& r) {
  json rows = json::array();
  for (const PeerRow& row : r.rows)
    rows.push_back({{"library", row.library},
                    {"version", row.version},
                    {"precision", row.precision},
                    {"method", row.method},
                    {"k", row.k},
                    {"promise", to_string(row.promise)},
                    {"containment", property_json(row.containment, false)},
                    {"overlap", property_json(row.overlap, true)}});
  return {{"cases_per_property", r.options.cases},
          {"seed", r.options.seed},
          {"own_violations", r.own_violations()},
          {"rows", rows}};
}

std::string peers_markdown(const PeersReport& r) {
  fmt::memory_buffer out;
  const auto to = std::back_inserter(out);
  fmt::format_to(to,
                 "## Peers\n\nThe project's own k-DOPs (`fdhcert`, promise: conservative) beside "
                 "other libraries' boxes (promise: none; counted, not held), on the same {} "
                 "random point sets and {} pairs of exactly touching point sets, seed {} "
                 "(docs/peers.md). Stored: the cases under the corpus's `peers/` replayed "
                 "(failing of replayed).\n\n"
                 "| library | version | method | k | property | checked | violations | first "
                 "shrunk cases | stored failing |\n|---|---|---|---|---|---|---|---|---|\n",
                 r.options.cases, r.options.cases, r.options.seed);
  for (const PeerRow& row : r.rows) {
    const std::string head = fmt::format("| {} | {} ({}) | `{}` | {} |", row.library, row.version,
                                         row.precision, row.method, row.k);
    fmt::format_to(to, "{} containment | {} |\n", head, property_cells(row.containment, false));
    fmt::format_to(to, "{} overlap | {} |\n", head, property_cells(row.overlap, true));
  }
  return fmt::to_string(out);
}

// overlapping: the pairs whose exact FDHs overlap (where a "disjoint" is a miss).
std::string peers_text(const PeersReport& r) {
  std::string out;
  static constexpr char kLine[] = "{:<9}{:<9}{:<18}{:>4}  {:<12}{:>8}{:>12}{:>11}{:>8}  {}\n";
  out += fmt::format("{} random point sets and {} touching pairs, seed {}\n", r.options.cases,
                     r.options.cases, r.options.seed);
  out += fmt::format(kLine, "library", "version", "method", "k", "property", "checked",
                     "overlapping", "violations", "stored", "first shrunk case");
  for (const PeerRow& row : r.rows)
    for (const PeerProperty* p : {&row.containment, &row.overlap}) {
      const bool overlap = p == &row.overlap;
      out += fmt::format(kLine, row.library, row.version.substr(0, 8), row.method, row.k,
                         overlap ? "overlap" : "containment", p->checked,
                         overlap ? std::to_string(p->exact_overlaps) : "-", p->violations,
                         fmt::format("{}/{}", p->stored_failing, p->stored),
                         p->shrunk.empty() ? "-" : p->shrunk.front());
    }
  return out;
}

}  // namespace fdh::verify

// Peers certified side by side (docs/peers.md): the project's own k-DOPs and every peer
// library's boxes (verify/peers/) on the same point sets, through the one checker, for two
// properties. Containment: each slab contains the exact extent of the points (check_box).
// Overlap: the boxes of two point sets whose exact hulls touch overlap wherever the exact FDHs
// along the method's directions do (check_overlap; a missed overlap is the failure). The own
// rows promise both (Promise::Conservative) and must show 0; the peers promise nothing: their
// violations are counted, the first ones shrunk and saved, and the stored ones replayed.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/os/progress.hpp"

namespace fdh::verify {

struct PeerOptions {
  bool quick = false;
  std::uint64_t seed = 1;
  long cases = -1;         // point sets, and pairs, per property; -1: 300 quick, 20000 full
  int keep = -1;           // shrunk cases kept per method and property; -1: 1 quick, 3 full
  std::string save_dir;    // shrunk cases go to <save_dir>/<library>/; empty: not saved
  std::string saved_name;  // how the results name save_dir (a staged output's final folder,
                           // fdh/os/output_folder.hpp); empty: save_dir
  std::string replay_dir;  // stored cases replayed from here (corpus/peers); empty: none
  ProgressSink progress;   // hears the cases checked per property
};

struct PeerProperty {
  long checked = 0;         // point sets (containment) or pairs (overlap), generated
  long exact_overlaps = 0;  // overlap: pairs whose exact FDHs overlap
  long violations = 0;      // a slab misses the exact extent; a "no" where the exact FDHs overlap
  std::vector<std::string> shrunk;      // the saved shrunk cases (paths), the first few
  long stored = 0, stored_failing = 0;  // stored cases replayed: a peer's own, still failing
};

struct PeerRow {
  std::string library, version, precision;  // "fdhcert" (commit) for the project's own
  std::string method, summary;
  int k = 0;
  Promise promise = Promise::None;
  PeerProperty containment, overlap;
};

struct PeersReport {
  PeerOptions options;
  std::vector<PeerRow> rows;        // the project's own k-DOPs first, then each peer's methods
  std::string first_own_violation;  // an own row's first violation and its saved case, or ""

  long own_checks() const;      // cases checked and stored cases replayed, on the own rows
  long own_violations() const;  // their violations and stored cases failing

 private:
  long own_sum(long PeerProperty::*first, long PeerProperty::*second) const;
};

// Throws InputError for a bad stored case, std::runtime_error when a case cannot be saved.
PeersReport certify_peers(const PeerOptions& options);

nlohmann::ordered_json peers_json(const PeersReport& r);
// The table `fdhcert peers` prints: one row per method and property (checked, overlapping,
// violations, stored cases failing, the first shrunk case).
std::string peers_text(const PeersReport& r);
// A "## Peers" section: one row per method and property, own rows first.
std::string peers_markdown(const PeersReport& r);

}  // namespace fdh::verify

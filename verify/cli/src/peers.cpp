// fdhcert peers: the project's own k-DOPs beside FCL's and Bullet's boxes (docs/peers.md).
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "fdh/os/atomic_file.hpp"
#include "fdh/peer_certify/peer_certify.hpp"
#include "suite_commands.hpp"

namespace fdh::verify {
namespace {

const char* const kPeersAbout =
    R"(certify other libraries' boxes beside the project's own k-DOPs

Runs the project's k-DOPs (k = 6, 14, 18, 26; promise: conservative) and every
peer library's boxes (FCL 0.7's KDOP<16>, <18>, <24>; Bullet 3.24 in double:
btDbvtAabbMm::FromPoints, btConvexHullShape and btBvhTriangleMeshShape getAabb;
promise: none) on the same point sets, through the one checker:
  - containment: on N random point sets with full-precision coordinates, each
    slab contains the exact extent (GMP rationals) of the points;
  - overlap: on N pairs of point sets built to touch exactly (a shared point,
    or a contact plane along one of the 13 integer directions), the boxes
    overlap wherever the exact FDHs along the method's directions do.
The first violations of each method and property are shrunk (fewer points,
shorter coordinates, toward the origin) and saved as OUT/<library>/
<method>-<property>-<hash>.txt; then every stored case under CORPUS/peers is
replayed. certify runs the same (saving into its own folder).)";

const char* const kPeersFooter =
    R"(Exit status 1 when one of the project's own k-DOPs fails (a peer's failures
are counted, never an error). --json prints the "peers" object of
certificate.json (docs/formats.md).)";

struct PeersCommand {
  PeerOptions peers;
  std::string corpus = "corpus";
  bool json = false;
  int threads = 0;  // 0: every core
};

int run_peers(PeersCommand& cmd, const Io& io) {
  if (!cmd.peers.save_dir.empty()) check_output_dir(cmd.peers.save_dir);
  cmd.peers.replay_dir = (std::filesystem::path(cmd.corpus) / "peers").string();
  const ThreadLimit threads(cmd.threads);
  ProgressLine progress(io.err, progress_wanted(io, cmd.json));
  cmd.peers.progress = progress.sink();
  const PeersReport r = certify_peers(cmd.peers);
  progress.clear();
  if (cmd.json)
    print_json(io.out, peers_json(r));
  else
    io.out << peers_text(r);
  if (r.first_own_violation.empty()) return 0;
  io.err << "fdhcert: peers: " << r.first_own_violation << "\n";
  return 1;
}

}  // namespace

Command add_peers(CLI::App& app) {
  auto cmd = std::make_shared<PeersCommand>();
  cmd->peers.save_dir = "corpus/peers";
  CLI::App* sub = add_command(app, "peers", kPeersAbout, kPeersFooter);
  sub->add_flag("--quick", cmd->peers.quick, "300 cases per property and 1 shrunk case kept");
  add_seed_option(*sub, cmd->peers.seed, "seed of the point sets (default 1)");
  add_number_option(*sub, "--cases", cmd->peers.cases,
                    "point sets, and pairs, per property (default 20000; 300 with --quick)", "N",
                    0L, 1L << 30);
  add_number_option(*sub, "--keep", cmd->peers.keep,
                    "shrunk cases saved per method and property (default 3; 1 with --quick)", "N",
                    0, 1000);
  sub->add_option("--out", cmd->peers.save_dir,
                  "shrunk cases go to OUT/<library>/ (default: corpus/peers)")
      ->type_name("DIR");
  sub->add_option("--corpus", cmd->corpus, "stored cases are replayed from CORPUS/peers")
      ->type_name("DIR");
  sub->add_flag("--json", cmd->json, "JSON instead of a table");
  add_threads_option(*sub, cmd->threads, "the checks");
  return {sub, [cmd](const Io& io) { return run_peers(*cmd, io); }};
}

}  // namespace fdh::verify

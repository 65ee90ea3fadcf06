#include "peer_ratios.hpp"

#include <fmt/format.h>

#include "cloth_on_table.hpp"

namespace fdh::bench {

void print_peer_ratios(const std::map<std::string, double>& seconds, std::ostream& out) {
  struct Pair {
    const char *peer, *ours, *what;
  };
  const Pair pairs[] = {
      {"bullet_collideTT", "tree_traverse<18>", "Bullet btDbvt collideTT / our traversal, k=18"},
      {"fcl_refit", "tree_refit<18>", "FCL BVHModel<KDOP<18>> refit / our refit, k=18"},
      {"fcl_collide", "tree_collide", "FCL collide / our traversal + narrow phase, k=18"},
  };
  out << "\npeers on the same cloth and table (peer time / ours; > 1: ours is faster)\n";
  out << fmt::format("{:<50}", "");
  for (const int g : kTreeGrids) out << fmt::format("{:>10}", fmt::format("{}x{}", g, g));
  out << "\n";
  for (const Pair& p : pairs) {
    out << fmt::format("{:<50}", p.what);
    for (const int g : kTreeGrids) {
      const auto a = seconds.find(fmt::format("{}/{}", p.peer, g));
      const auto b = seconds.find(fmt::format("{}/{}", p.ours, g));
      out << (a == seconds.end() || b == seconds.end()
                  ? fmt::format("{:>10}", "-")
                  : fmt::format("{:>10.2f}", a->second / b->second));
    }
    out << "\n";
  }
}

}  // namespace fdh::bench

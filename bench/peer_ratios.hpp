// The peers beside ours, from the same run: each peer's time divided by ours on the same cloth
// and table (> 1: ours is faster).
#pragma once

#include <map>
#include <ostream>
#include <string>

namespace fdh::bench {

// seconds: mean seconds per iteration of each benchmark run, by its name.
void print_peer_ratios(const std::map<std::string, double>& seconds, std::ostream& out);

}  // namespace fdh::bench

// The step's loops on every core the run allows, with results that do not depend on the thread
// count (fdh/parallel/chunks.hpp), and the tree passes built on them (fdh/parallel/bottom_up.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "fdh/parallel/bottom_up.hpp"
#include "fdh/parallel/chunks.hpp"

namespace fdh::cloth {

// The step's chunked loops (fdh/parallel/chunks.hpp): on every core, never isolated (they are
// short, and start no parallel loop of their own).
using parallel::for_chunks;
using parallel::gather_chunks;

// The tree passes (fdh/parallel/bottom_up.hpp).
using parallel::BottomUp;
using parallel::kParallelNodes;
using parallel::subtree_end;

}  // namespace fdh::cloth

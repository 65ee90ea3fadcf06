// The suite's loops on every core the run allows (oneTBB; `--threads` caps it through
// tbb::global_control), with results that do not depend on the thread count: [0, n) is cut into
// chunks fixed by n and the grain alone, each chunk fills its own part, and the caller merges
// the parts in chunk order. While a method that must stay on one thread is registered (a
// plug-in's: Method::one_thread), the chunks run one after another on the calling thread.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "fdh/check/registry.hpp"

namespace fdh::verify {

// run(c) for c in [0, chunks): on every core, or one after another on this thread while a
// one_thread method is registered. A chunk that runs a parallel loop of its own (a scene's
// cloth, a frame's queries) waits for that loop's work only: isolated, its thread takes no
// other chunk meanwhile, so a chunk never sits blocked under another on one stack.
template <class Run>
void run_chunks(std::size_t chunks, const Run& run) {
  if (chunks <= 1 || !registry_thread_safe()) {
    for (std::size_t c = 0; c < chunks; ++c) run(c);
    return;
  }
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, chunks, 1),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c < r.end(); ++c)
          tbb::this_task_arena::isolate([&] { run(c); });
      },
      tbb::simple_partitioner());
}

// fill(begin, end, part) for the chunks [c·grain, (c+1)·grain) of [0, n), each part starting as
// a copy of `zero`; the parts in chunk order.
template <class Part, class Fill>
std::vector<Part> parts_in_order(std::size_t n, std::size_t grain, const Part& zero,
                                 const Fill& fill) {
  grain = std::max<std::size_t>(grain, 1);
  std::vector<Part> parts((n + grain - 1) / grain, zero);
  run_chunks(parts.size(),
             [&](std::size_t c) { fill(c * grain, std::min(n, (c + 1) * grain), parts[c]); });
  return parts;
}

// f(i) for every i in [0, n), chunks of `grain` at a time; f writes only what is i's own.
template <class F>
void for_each_index(std::size_t n, std::size_t grain, const F& f) {
  grain = std::max<std::size_t>(grain, 1);
  run_chunks((n + grain - 1) / grain, [&](std::size_t c) {
    for (std::size_t i = c * grain; i < std::min(n, (c + 1) * grain); ++i) f(i);
  });
}

}  // namespace fdh::verify

// Deterministic loops on every core the run allows (oneTBB), written once for cloth/ and the
// suite (verify/check/include/fdh/check/parallel.hpp): [0, n) is cut into chunks fixed by n and
// the grain alone, each chunk writes only its own outputs, and whatever is gathered from chunks
// is merged in chunk order, so results do not depend on the thread count.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fdh::parallel {

// How chunks run.
struct Chunking {
  // false: one after another on the calling thread (a method that must stay on one thread).
  bool parallel = true;
  // A chunk that runs a parallel loop of its own (a scene's cloth, a frame's queries) waits for
  // that loop's work only: isolated, its thread takes no other chunk meanwhile, so a chunk never
  // sits blocked under another on one stack. Off for the cloth's short inner loops.
  bool isolate = false;
};

// run(c) for c in [0, chunks).
template <class Run>
void run_chunks(std::size_t chunks, const Run& run, Chunking how = {}) {
  if (chunks <= 1 || !how.parallel) {
    for (std::size_t c = 0; c < chunks; ++c) run(c);
    return;
  }
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, chunks, 1),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c < r.end(); ++c) {
          if (how.isolate)
            tbb::this_task_arena::isolate([&] { run(c); });
          else
            run(c);
        }
      },
      tbb::simple_partitioner());
}

// f(begin, end) for the chunks [c·grain, (c+1)·grain) of [0, n) (the last may be shorter).
template <class F>
void for_chunks(std::size_t n, std::size_t grain, const F& f, Chunking how = {}) {
  grain = std::max<std::size_t>(grain, 1);
  run_chunks((n + grain - 1) / grain,
             [&](std::size_t c) { f(c * grain, std::min(n, (c + 1) * grain)); }, how);
}

// f(i) for every i in [0, n), chunks of `grain` at a time; f writes only what is i's own.
template <class F>
void for_each_index(std::size_t n, std::size_t grain, const F& f, Chunking how = {}) {
  for_chunks(
      n, grain,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) f(i);
      },
      how);
}

// fill(begin, end, part) for the chunks of [0, n), each part starting as a copy of `zero`; the
// parts in chunk order.
template <class Part, class Fill>
std::vector<Part> parts_in_order(std::size_t n, std::size_t grain, const Part& zero,
                                 const Fill& fill, Chunking how = {}) {
  grain = std::max<std::size_t>(grain, 1);
  std::vector<Part> parts((n + grain - 1) / grain, zero);
  for_chunks(
      n, grain, [&](std::size_t begin, std::size_t end) { fill(begin, end, parts[begin / grain]); },
      how);
  return parts;
}

// Runs f(c, part) for chunks c = 0 .. chunks - 1, then appends the parts to `all` in chunk
// order: the same `all` for any thread count. `parts` is kept by the caller to reuse its memory.
template <class T, class F>
void gather_chunks(std::size_t chunks, std::vector<std::vector<T>>& parts, std::vector<T>& all,
                   const F& f, Chunking how = {}) {
  parts.resize(chunks);
  run_chunks(
      chunks,
      [&](std::size_t c) {
        parts[c].clear();
        f(c, parts[c]);
      },
      how);
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
}

}  // namespace fdh::parallel

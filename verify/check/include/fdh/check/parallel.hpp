// The suite's loops on every core the run allows (`--threads` caps it through
// tbb::global_control), with results that do not depend on the thread count
// (fdh/parallel/chunks.hpp). While a method that must stay on one thread is registered (a
// plug-in's: Method::one_thread), the chunks run one after another on the calling thread; a
// chunk is isolated, as it may run a parallel loop of its own.
#pragma once

#include <cstddef>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/parallel/chunks.hpp"

namespace fdh::verify {

inline parallel::Chunking suite_chunking() {
  return {registry_thread_safe(), true};
}

// run(c) for c in [0, chunks).
template <class Run>
void run_chunks(std::size_t chunks, const Run& run) {
  parallel::run_chunks(chunks, run, suite_chunking());
}

// fill(begin, end, part) for the chunks [c·grain, (c+1)·grain) of [0, n), each part starting as
// a copy of `zero`; the parts in chunk order.
template <class Part, class Fill>
std::vector<Part> parts_in_order(std::size_t n, std::size_t grain, const Part& zero,
                                 const Fill& fill) {
  return parallel::parts_in_order(n, grain, zero, fill, suite_chunking());
}

// f(i) for every i in [0, n), chunks of `grain` at a time; f writes only what is i's own.
template <class F>
void for_each_index(std::size_t n, std::size_t grain, const F& f) {
  parallel::for_each_index(n, grain, f, suite_chunking());
}

}  // namespace fdh::verify

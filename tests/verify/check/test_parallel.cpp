// The suite's parallel loops (fdh/check/parallel.hpp): chunks fixed by the input alone, merged
// in order, the same for any thread count; on the calling thread while a plug-in-like
// one_thread method is registered.
#include "fdh/check/parallel.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <set>
#include <thread>
#include <vector>

namespace fdh::verify {
namespace {

// Each chunk's [begin, end), in the order the parts come back.
std::vector<std::pair<std::size_t, std::size_t>> chunks(std::size_t n, std::size_t grain) {
  using Range = std::pair<std::size_t, std::size_t>;
  return parts_in_order(n, grain, Range{}, [](std::size_t b, std::size_t e, Range& part) {
    part = {b, e};
  });
}

TEST(Parallel, ChunksDependOnTheInputAloneAndComeBackInOrder) {
  const std::vector<std::pair<std::size_t, std::size_t>> want = {{0, 4}, {4, 8}, {8, 10}};
  for (const std::size_t threads : {1, 2, 64}) {  // 64: more threads than chunks
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    EXPECT_EQ(chunks(10, 4), want) << threads;
    EXPECT_EQ(chunks(3, 16).size(), 1u) << threads;  // fewer items than a grain
    EXPECT_TRUE(chunks(0, 4).empty()) << threads;
  }
}

TEST(Parallel, EveryIndexOnceForAnyThreadCount) {
  for (const std::size_t threads : {1, 2, 64}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    std::vector<int> seen(1000);
    for_each_index(seen.size(), 7, [&](std::size_t i) { seen[i] += int(i) + 1; });
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], int(i) + 1) << threads;
  }
}

// A plug-in promises nothing about threads (docs/plugins.md): while one is registered, every
// chunk runs on the calling thread.
TEST(Parallel, AOneThreadMethodKeepsEveryChunkOnTheCallingThread) {
  Method m;
  m.name = "one-thread-test";
  m.one_thread = true;
  add_methods({m}, {});
  EXPECT_FALSE(registry_thread_safe());
  std::set<std::thread::id> ids;
  const auto parts = parts_in_order(
      std::size_t(64), 1, std::thread::id{},
      [](std::size_t, std::size_t, std::thread::id& id) { id = std::this_thread::get_id(); });
  remove_added_methods();
  ids.insert(parts.begin(), parts.end());
  EXPECT_EQ(ids, std::set<std::thread::id>{std::this_thread::get_id()});
  EXPECT_TRUE(registry_thread_safe());
}

}  // namespace
}  // namespace fdh::verify

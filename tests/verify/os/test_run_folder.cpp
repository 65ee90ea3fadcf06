#include "fdh/os/run_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/os/atomic_file.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

TEST(RunFolder, AManifestReadsBackAndRefusesAnotherTitle) {
  const fs::path d = fresh_temp_dir("run_folder_manifest");
  const Manifest m{"a run", {{"method", "robust"}, {"shard", "1/2"}}};
  write_file_atomically((d / "manifest").string(), m.text());
  const std::optional<Manifest> back = Manifest::read((d / "manifest").string(), "a run");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->entries, m.entries);
  EXPECT_FALSE(Manifest::read((d / "manifest").string(), "another run"));
  EXPECT_FALSE(Manifest::read((d / "absent").string(), "a run"));
  fs::remove_all(d);
}

TEST(RunFolder, MarkerNamesRoundTripAndRejectOthers) {
  EXPECT_EQ(marker_name({5, 10}), "cases-5-10");
  const std::optional<IndexRange> r = parse_marker_name("cases-5-10");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->begin, 5);
  EXPECT_EQ(r->end, 10);
  for (const char* bad : {"cases-5-5", "cases-10-5", "cases-05-10", "cases-5-10x", "case-5-10"})
    EXPECT_FALSE(parse_marker_name(bad)) << bad;
}

TEST(RunFolder, CoverageListsTheMarkersAndTheGapsBetweenThem) {
  const fs::path d = fresh_temp_dir("run_folder_coverage");
  for (const IndexRange r : {IndexRange{0, 10}, IndexRange{20, 30}, IndexRange{40, 60}})
    write_file_atomically((d / marker_name(r)).string(), "0\n");
  write_file_atomically((d / "cases-5-8").string(), "0\n");  // overlaps the first: ignored
  const Coverage c = coverage_of(d.string(), 0, 50);         // 40-60 lies outside
  ASSERT_EQ(c.done.size(), 2u);
  EXPECT_EQ(c.done_count(), 20);
  ASSERT_EQ(c.todo.size(), 2u);
  EXPECT_EQ(c.todo[0].begin, 10);
  EXPECT_EQ(c.todo[0].end, 20);
  EXPECT_EQ(c.todo[1].begin, 30);
  EXPECT_EQ(c.todo[1].end, 50);
  fs::remove_all(d);
}

}  // namespace
}  // namespace fdh::verify

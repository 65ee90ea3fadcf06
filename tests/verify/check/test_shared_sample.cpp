// The CCD benchmark sample in ../shared (exact ground truth computed by its authors): exact
// twin must agree with every truth, and every method that promises the exact verdict with the
// twin, through the checker. Skipped when ../shared is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "fdh/check/checker.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sample_files(const std::string& kind_folder) {
  std::vector<fs::path> files;
  const fs::path root = FDH_CCD_SAMPLE;  // the build's FDH_CCD_SAMPLE, empty for none
  if (!fs::is_directory(root)) return files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.path().extension() == ".csv" && e.path().parent_path().filename() == kind_folder)
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every query of one kind folder: static and moving vertex-face, or edge-edge.
void check_kind(const std::string& folder, std::size_t at_least) {
  const std::vector<fs::path> files = sample_files(folder);
  if (files.empty()) GTEST_SKIP() << "no CCD benchmark sample (FDH_CCD_SAMPLE)";
  const std::vector<Method> promised = promised_methods();
  std::size_t checked = 0;
  for (const fs::path& f : files) {
    for (const QueryRecord& r : read_query_file(f.string())) {
      ASSERT_TRUE(r.has_truth());
      SCOPED_TRACE(r.file + ":" + std::to_string(r.line));
      const Query& q = r.query;
      const bool twin = twin_hit(q);
      EXPECT_EQ(twin_matches_truth(stated(r.truth), twin), true);
      for (const Method& m : promised) EXPECT_TRUE(check(m, q, twin).kept) << m.name;
      ++checked;
    }
  }
  EXPECT_GT(checked, at_least);
}

TEST(SharedSample, VertexFaceExactMatchesGroundTruthAndRobustMatchesExact) {
  check_kind("vertex-face", 1400);
}

TEST(SharedSample, EdgeEdgeExactMatchesGroundTruthAndRobustMatchesExact) {
  check_kind("edge-edge", 1300);
}

TEST(SharedSample, EveryFileParses) {
  const std::vector<fs::path> vf = sample_files("vertex-face"), ee = sample_files("edge-edge");
  if (vf.empty() && ee.empty()) GTEST_SKIP() << "no CCD benchmark sample (FDH_CCD_SAMPLE)";
  for (const auto& files : {vf, ee})
    for (const fs::path& f : files) EXPECT_NO_THROW(read_query_file(f.string())) << f;
}

}  // namespace
}  // namespace fdh::verify

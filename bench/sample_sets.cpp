#include "sample_sets.hpp"

#include <algorithm>
#include <filesystem>

#include "fdh/io/query_io.hpp"

namespace fdh::bench {

std::map<std::string, std::vector<Query>> sample_sets() {
  namespace fs = std::filesystem;
  std::map<std::string, std::vector<Query>> sets;
  const fs::path root = FDH_CCD_SAMPLE;  // the build's FDH_CCD_SAMPLE, empty for none
  if (!fs::is_directory(root)) return sets;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    const auto kind = verify::kind_from_folder(f.string());
    if (!kind) continue;
    const std::string set = f.parent_path().parent_path().filename().string();
    for (const verify::QueryRecord& r : verify::read_benchmark_csv(f.string(), *kind))
      sets[set].push_back(r.query);
  }
  return sets;
}

}  // namespace fdh::bench

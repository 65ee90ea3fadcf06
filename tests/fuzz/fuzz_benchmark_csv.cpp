// libFuzzer target: the CCD benchmark's CSV reader (read_benchmark_csv) on arbitrary bytes, read
// as vertex-face and as edge-edge queries.
#include <cstddef>
#include <cstdint>

#include "fdh/io/query_io.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fdh::fuzz::InputFile file(".csv");
  const std::string& path = file.write(data, size);
  for (const auto kind : {fdh::QueryKind::VertexFace, fdh::QueryKind::EdgeEdge})
    fdh::fuzz::only_input_errors([&] { fdh::verify::read_benchmark_csv(path, kind); });
  return 0;
}

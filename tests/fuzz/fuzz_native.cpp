// libFuzzer target: the native query reader (read_native) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fdh/io/query_io.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fdh::fuzz::InputFile file(".vf");
  const std::string& path = file.write(data, size);
  fdh::fuzz::only_input_errors([&] { fdh::verify::read_native(path); });
  return 0;
}

// libFuzzer target: the scene reader (read_scene) on arbitrary bytes.
#include <cstddef>
#include <cstdint>

#include "fdh/io/scene_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fdh::fuzz::InputFile file(".scene");
  const std::string& path = file.write(data, size);
  fdh::fuzz::only_input_errors([&] { fdh::verify::read_scene(path); });
  return 0;
}

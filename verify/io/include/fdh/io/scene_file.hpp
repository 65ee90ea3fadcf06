// The scene format of corpus/scenes/*.scene (docs/formats.md): one keyword per line with its
// values, '#' starts a comment, and every keyword is optional.
#pragma once

#include <string>

#include "fdh/cloth/scene.hpp"

namespace fdh::verify {

// Throws InputError naming the file and line.
cloth::Scene read_scene(const std::string& path);

}  // namespace fdh::verify

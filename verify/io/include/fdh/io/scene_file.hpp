// The scene format of corpus/scenes/*.scene (docs/formats.md): one keyword per line with its
// values, '#' starts a comment, and every keyword is optional.
#pragma once

#include <string>

#include "fdh/cloth/scene.hpp"

namespace fdh::verify {

// Reads and checks a scene (check_scene). Throws InputError naming the file and line.
cloth::Scene read_scene(const std::string& path);

// Every value of `scene` against the ranges and bounds of docs/limits.md, and the rules that
// join two values (damping·dt <= 1; a stable step of at least 1e-9 s). read_scene does this; a
// caller that changes a scene after reading it (the command line's --grid, --thickness) calls
// it again. Throws InputError naming `path` (no line).
void check_scene(const cloth::Scene& scene, const std::string& path);

}  // namespace fdh::verify

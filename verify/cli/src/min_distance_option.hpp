// --min-distance D on fuzz and certify: the minimum separation δ (Query::min_distance) the
// command asks its queries at, read as the native format reads it (docs/formats.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace fdh::verify {

// --min-distance D into `d`: a finite number >= 0, decimal (correctly rounded) or hex-float,
// taken at the double's exact value; anything else is a usage error naming it. `what` says
// what D asks of the command (the help text).
CLI::Option* add_min_distance_option(CLI::App& cmd, double& d, const std::string& what);

}  // namespace fdh::verify

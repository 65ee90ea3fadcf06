// The parameters that fix a fuzz run's cases (--chunk and --threads do not), and how they are
// recorded in the run's manifest (fdh/os/run_folder.hpp). Private to fdh_fuzz.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "fdh/os/run_folder.hpp"

namespace fdh::verify {

struct FuzzParams {
  std::string method, family;
  std::uint64_t seed = 0;
  long count = 0;
  int shard = 0, shards = 1;  // shard 0-based
  bool metamorphic = false;   // recorded only when set: older manifests stay valid
  bool toi = false;           // so is the TOI mode, with its width and tolerance
  double width = 0, tolerance = 0;
  double min_distance = 0;  // δ; recorded only when not 0, so older manifests stay valid

  bool operator==(const FuzzParams& o) const;
  // The run's folder under OUT/.fuzz: method.family.seedS.countN.shardIofS, prefixed
  // "metamorphic." or "toi.wW.tolT." (W and T as C hexadecimal floats) in those modes.
  std::string folder_name() const;
  // The command-line options that give this run.
  std::string options() const;
  Manifest manifest() const;
  // A manifest's parameters; nullopt for one that records no fuzz run.
  static std::optional<FuzzParams> of(const Manifest& m);
  static std::optional<FuzzParams> read(const std::string& manifest_path);

  long first() const;
  long last() const;
};

}  // namespace fdh::verify

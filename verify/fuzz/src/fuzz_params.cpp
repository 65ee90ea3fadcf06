#include "fuzz_params.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "fdh/fuzz/fuzz.hpp"

namespace fdh::verify {
namespace {

const std::string kTitle = "fdhcert fuzz run";

// One value read whole from `text`, or false.
template <class T>
bool parse(const std::string& text, T& value) {
  std::istringstream in(text);
  return (in >> value) && in.peek() == EOF;
}

// A double written by hex(), read whole.
bool parse_hex(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0';
}

// A double exactly, as a C hexadecimal float ("0x1p-30").
std::string hex(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", v);
  return text;
}

bool parse_shard(const std::string& text, FuzzParams& p) {
  std::istringstream in(text);
  char slash = 0;
  if (!(in >> p.shard >> slash >> p.shards) || slash != '/' || in.peek() != EOF) return false;
  --p.shard;
  return true;
}

}  // namespace

bool FuzzParams::operator==(const FuzzParams& o) const {
  return method == o.method && family == o.family && seed == o.seed && count == o.count &&
         shard == o.shard && shards == o.shards && metamorphic == o.metamorphic && toi == o.toi &&
         (!toi || (width == o.width && tolerance == o.tolerance)) && min_distance == o.min_distance;
}

std::string FuzzParams::folder_name() const {
  const std::string mode = metamorphic ? "metamorphic."
                           : toi       ? "toi.w" + hex(width) + ".tol" + hex(tolerance) + "."
                                       : "";
  const std::string delta = min_distance != 0 ? "d" + hex(min_distance) + "." : "";
  return delta + mode + method + "." + family + ".seed" + std::to_string(seed) + ".count" +
         std::to_string(count) + ".shard" + std::to_string(shard + 1) + "of" +
         std::to_string(shards);
}

std::string FuzzParams::options() const {
  const std::string mode =
      metamorphic ? "--metamorphic "
      : toi       ? "--toi --width " + hex(width) + " --toi-tolerance " + hex(tolerance) + " "
                  : "";
  const std::string delta =
      min_distance != 0 ? "--min-distance " + hex(min_distance) + " " : std::string();
  return delta + mode + std::string("--method ") + method + " --family " + family + " --seed " +
         std::to_string(seed) + " --count " + std::to_string(count) + " --shard " +
         std::to_string(shard + 1) + "/" + std::to_string(shards);
}

Manifest FuzzParams::manifest() const {
  Manifest m{kTitle,
             {{"method", method},
              {"family", family},
              {"seed", std::to_string(seed)},
              {"count", std::to_string(count)},
              {"shard", std::to_string(shard + 1) + "/" + std::to_string(shards)}}};
  if (metamorphic) m.entries.emplace_back("mode", "metamorphic");
  if (toi) {
    m.entries.emplace_back("mode", "toi");
    m.entries.emplace_back("width", hex(width));
    m.entries.emplace_back("toi-tolerance", hex(tolerance));
  }
  if (min_distance != 0) m.entries.emplace_back("min-distance", hex(min_distance));
  return m;
}

std::optional<FuzzParams> FuzzParams::of(const Manifest& m) {
  FuzzParams p;
  bool ok[5] = {};  // method, family, seed, count, shard
  for (const auto& [key, value] : m.entries) {
    if (key == "method") {
      p.method = value, ok[0] = true;
    } else if (key == "family") {
      p.family = value, ok[1] = true;
    } else if (key == "seed") {
      ok[2] = parse(value, p.seed);
    } else if (key == "count") {
      ok[3] = parse(value, p.count);
    } else if (key == "shard") {
      ok[4] = parse_shard(value, p);
    } else if (key == "mode" && value == "metamorphic") {
      p.metamorphic = true;
    } else if (key == "mode" && value == "toi") {
      p.toi = true;
    } else if (key == "width") {
      if (!parse_hex(value, p.width)) return std::nullopt;
    } else if (key == "toi-tolerance") {
      if (!parse_hex(value, p.tolerance)) return std::nullopt;
    } else if (key == "min-distance") {
      if (!parse_hex(value, p.min_distance) || !(p.min_distance > 0)) return std::nullopt;
    } else {
      return std::nullopt;
    }
  }
  for (const bool b : ok)
    if (!b) return std::nullopt;
  if (p.toi && !(p.width > 0)) return std::nullopt;
  if (p.count < 0 || p.shards < 1 || p.shard < 0 || p.shard >= p.shards) return std::nullopt;
  return p;
}

std::optional<FuzzParams> FuzzParams::read(const std::string& manifest_path) {
  const std::optional<Manifest> m = Manifest::read(manifest_path, kTitle);
  return m ? of(*m) : std::nullopt;
}

long FuzzParams::first() const {
  return shard_begin(count, shard, shards);
}

long FuzzParams::last() const {
  return shard_begin(count, shard + 1, shards);
}

}  // namespace fdh::verify

// The generator families: every construction of queries the suite draws from, static and
// moving, in one registry. Coordinates are dyadic (small integers over powers of two), so a
// path that passes exactly through an edge or a vertex really does, and a construction often
// knows the truth on its own, and its contact kind or time: an oracle that does not depend on
// `exact`. The families are listed in docs/methods.md.
//
// This header needs no RapidCheck: callers draw a case from a seed. Property tests use the
// families as RapidCheck generators through fdh/gen/rapidcheck.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fdh/io/query_record.hpp"
#include "fdh/query.hpp"

namespace fdh::verify {

// One case of a family. Its record (record()) is named by the family.
struct Generated {
  std::string family;  // the family's name
  Query query;
  Truth truth = Truth::Unknown;  // where the construction decides it
  std::string kind;  // the contact kind the construction guarantees ("edge", ...), or ""
  std::string time;  // the exact earliest contact time it guarantees ("p/q"), or ""

  // As a record without a file: the family's name as its id, the construction's truth.
  QueryRecord record() const { return {query, family, truth, "", 0}; }
};

struct Family {
  std::string name;     // as on the command line: "angled", "generic-moving", ...
  bool moving = false;  // moving vertex-face or edge-edge queries; else static vertex-face
  std::string summary;  // what the construction draws, in one line
  // The construction. It draws through RapidCheck, so it runs only inside a generator: call
  // it through generate(), shrunk_failure() or gen_family() (fdh/gen/rapidcheck.hpp), which
  // also set the case's family to `name`.
  Generated (*construct)() = nullptr;
};

// Every family: the 15 static ones, then the 9 moving ones, always in this order (certify
// draws the j-th family from stream j).
const std::vector<Family>& all_families();

// The minimum-separation families (issue 30; names "delta-..."): every case at δ > 0
// (Query::min_distance), D or D (1 ± 2^-40) where the construction knows the minimum distance D
// exactly, with its truth. Apart from all_families(), whose cases all ask for contact.
const std::vector<Family>& delta_families();

// The family of that name (all_families() or delta_families()), or nullptr.
const Family* family_named(const std::string& name);

// The names of the static (moving = false) or of the moving families, in registry order.
std::vector<std::string> family_names(bool moving);

// Case `seed` of family f: the same seed gives the same case, on every run and every machine.
Generated generate(const Family& f, std::uint64_t seed);

// Case `seed` of family f shrunk while it still fails, or nullopt when the case does not fail at
// all: a greedy descent through RapidCheck's shrink tree (fdh/gen/shrink.hpp), then a greedy
// pass over the query itself (fdh/gen/simplify.hpp: less motion, nearer the origin, shorter
// coordinates). Every step keeps the case's kind (fdh/gen/case_kind.hpp: static, moving
// vertex-face or edge-edge, as drawn, and no primitive collapsed to coincident points that the
// case drawn had whole): a step that leaves it is refused like one that no longer fails. A caller
// that wants the failure's class kept (a false alarm stays a false alarm) says so in `fails`. Where
// the second pass changed the query, its truth, contact kind and time are unset.
std::optional<Generated> shrunk_failure(const Family& f, std::uint64_t seed,
                                        const std::function<bool(const Generated&)>& fails);

}  // namespace fdh::verify

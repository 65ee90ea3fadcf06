// The registry of generator families, and the ways to draw from one: by seed, shrunk, or as a
// RapidCheck generator.
#include "fdh/gen/families.hpp"

#include <utility>

#include "constructions.hpp"
#include "fdh/gen/case_kind.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "fdh/gen/shrink.hpp"
#include "fdh/gen/simplify.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {

const std::vector<Family>& all_families() {
  static const std::vector<Family> all = [] {
    std::vector<Family> v = static_families();
    for (Family& f : moving_families()) v.push_back(std::move(f));
    return v;
  }();
  return all;
}

const std::vector<Family>& delta_families() {
  static const std::vector<Family> all = min_distance_families();
  return all;
}

const Family* family_named(const std::string& name) {
  for (const Family& f : all_families())
    if (f.name == name) return &f;
  for (const Family& f : delta_families())
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<std::string> family_names(bool moving) {
  std::vector<std::string> names;
  for (const Family& f : all_families())
    if (f.moving == moving) names.push_back(f.name);
  return names;
}

// RapidCheck scales inRange by its size parameter (size 0 gives only the minimum). A family is
// a fixed distribution, so every case is drawn at the nominal size; shrinking still works.
rc::Gen<Generated> gen_family(const Family& f) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([name = f.name, construct = f.construct] {
                           Generated g = construct();
                           g.family = name;
                           return g;
                         }));
}

Generated generate(const Family& f, std::uint64_t seed) {
  return gen_family(f)(rc::Random(seed)).value();
}

std::optional<Generated> shrunk_failure(const Family& f, std::uint64_t seed,
                                        const std::function<bool(const Generated&)>& fails) {
  const rc::Shrinkable<Generated> s = gen_family(f)(rc::Random(seed));
  if (!fails(s.value())) return std::nullopt;
  // A step that leaves the kind of the case drawn is refused, as one that no longer fails is.
  const Query drawn = s.value().query;
  const auto keeps = [&](const Generated& h) { return keeps_kind(drawn, h.query) && fails(h); };
  Generated g = shrink_failure(s, keeps);
  const Query shrunk = g.query;
  g.query = simplify_failure(shrunk, [&g, &keeps](const Query& q) {
    Generated h = g;
    h.query = q;
    return keeps(h);
  });
  // A changed query is no longer the construction's: what it guaranteed no longer holds.
  if (!(g.query.x == shrunk.x)) g.truth = Truth::Unknown, g.kind.clear(), g.time.clear();
  return g;
}

void showValue(const Generated& g, std::ostream& os) {
  os << g.family << " (truth " << (g.truth == Truth::Unknown ? -1 : int(g.truth == Truth::Yes))
     << ")\n";
  write_native(os, g.record());
}

}  // namespace fdh::verify

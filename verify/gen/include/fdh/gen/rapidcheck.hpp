// The generator families and triangle soups as RapidCheck generators, for property tests.
// Every case is drawn at RapidCheck's nominal size, so a family is one fixed distribution;
// shrinking still works.
#pragma once

#include <rapidcheck.h>

#include <ostream>

#include "fdh/gen/families.hpp"
#include "fdh/gen/soup.hpp"

namespace fdh::verify {

rc::Gen<Generated> gen_family(const Family& f);
rc::Gen<Soup> gen_soup(int max_tris);

// For RapidCheck's counterexample output: the query as a native-format line.
void showValue(const Generated& g, std::ostream& os);

}  // namespace fdh::verify

// Peers: other libraries' bounding volumes, certified beside the project's own k-DOPs through
// the one checker (check/checker.hpp). Each library is one adapter file in verify/peers/src/
// that turns its boxes into BoxMethods carrying the library's own slab directions, and one line
// in src/libraries.def. Peers promise nothing the checker holds them to (Promise::None): their
// failures are counted and shrunk, never a broken certificate.
#pragma once

#include <string>
#include <vector>

#include "fdh/check/registry.hpp"

namespace fdh::verify {

struct PeerLibrary {
  std::string name;       // "fcl": also its folder under corpus/peers/
  std::string version;    // as the library's headers give it (FCL_VERSION, BT_BULLET_VERSION)
  std::string precision;  // the scalar its boxes are computed in: "double"
  std::vector<BoxMethod> methods;
};

// Every peer library built in, in libraries.def order.
std::vector<PeerLibrary> all_peer_libraries();

}  // namespace fdh::verify

// The peers' box methods by library and name, for the tests of verify/peers/.
#pragma once

#include <stdexcept>
#include <string>

#include "fdh/peers/peers.hpp"

namespace fdh::verify {

inline PeerLibrary peer_library(const std::string& library) {
  for (PeerLibrary& lib : all_peer_libraries())
    if (lib.name == library) return lib;
  throw std::invalid_argument("no peer library " + library);
}

inline BoxMethod peer_method(const std::string& library, const std::string& method) {
  for (BoxMethod& m : peer_library(library).methods)
    if (m.name == method) return m;
  throw std::invalid_argument("no peer method " + library + " " + method);
}

}  // namespace fdh::verify

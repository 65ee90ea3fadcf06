#include "fdh/peers/peers.hpp"

namespace fdh::verify {

#define FDH_PEER_LIBRARY(f) PeerLibrary f();
#include "libraries.def"
#undef FDH_PEER_LIBRARY

std::vector<PeerLibrary> all_peer_libraries() {
  return {
#define FDH_PEER_LIBRARY(f) f(),
#include "libraries.def"
#undef FDH_PEER_LIBRARY
  };
}

}  // namespace fdh::verify

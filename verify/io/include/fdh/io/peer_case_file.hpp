// Peer cases: one point set (containment) or two (overlap) on which a peer library's box
// failed, stored under corpus/peers/<library>/ (docs/formats.md, "peer cases"). Named by a hash
// of the points, so that the same case found twice is one file.
#pragma once

#include <string>
#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::verify {

struct PeerCase {
  std::string library, method, property;  // property: "containment" or "overlap"
  std::vector<Vec3> a, b;                 // b: the second set of an overlap case, else empty
};

// 16 hex digits (FNV-1a over the names and the coordinates' bits).
std::string peer_case_hash(const PeerCase& c);

// "<method>-<property>-<hash>.txt"
std::string peer_case_file_name(const PeerCase& c);

// `# comment` lines, `peer <library> <method> <property>`, then one `a x y z` or `b x y z` line
// per point, in hex-float so that reading it back gives the same doubles.
std::string peer_case_text(const PeerCase& c, const std::vector<std::string>& comments);

// Reads one case. Throws InputError naming FILE:LINE.
PeerCase read_peer_case(const std::string& path);

// The *.txt files below `dir`, sorted; none when `dir` does not exist. Throws InputError when
// the folder cannot be listed.
std::vector<std::string> list_peer_case_files(const std::string& dir);

}  // namespace fdh::verify

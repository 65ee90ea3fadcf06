#include "fdh/io/peer_case_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "fdh/io/case_files.hpp"
#include "fdh/io/case_hash.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

// A case file holds what a shrunk case needs, and far less than this.
constexpr std::size_t kMaxPoints = 100000;

std::vector<std::string> words(const std::string& line) {
  std::istringstream is(line);
  std::vector<std::string> w;
  for (std::string s; is >> s;) w.push_back(s);
  return w;
}

void read_point(const InputFile& in, const std::vector<std::string>& w, PeerCase& c) {
  if (w.size() != 4) throw InputError(in.path(), in.line(), "a point is `a|b x y z`");
  double xyz[3];
  for (int i = 0; i < 3; ++i) {
    std::string why;
    const auto v = parse_double(w[1 + i], why);
    if (!v) throw InputError(in.path(), in.line(), why);
    xyz[i] = *v;
  }
  const Vec3 p{xyz[0], xyz[1], xyz[2]};
  std::vector<Vec3>& set = w[0] == "a" ? c.a : c.b;
  if (set.size() >= kMaxPoints)
    throw InputError(in.path(), in.line(), "more than 100000 points in one set");
  set.push_back(p);
}

}  // namespace

std::string peer_case_hash(const PeerCase& c) {
  CaseHash h;
  for (const std::string* s : {&c.library, &c.method, &c.property})
    for (const char ch : *s) h.add(std::uint64_t(static_cast<unsigned char>(ch)));
  for (const auto* set : {&c.a, &c.b}) {
    h.add(set->size());
    for (const Vec3& p : *set)
      for (int i = 0; i < 3; ++i) h.add_coordinate(p[i]);
  }
  return h.hex();
}

std::string peer_case_file_name(const PeerCase& c) {
  return c.method + "-" + c.property + "-" + peer_case_hash(c) + ".txt";
}

std::string peer_case_text(const PeerCase& c, const std::vector<std::string>& comments) {
  std::ostringstream os;
  for (const std::string& line : comments) os << "# " << line << '\n';
  os << "peer " << c.library << ' ' << c.method << ' ' << c.property << '\n';
  const auto points = [&os](const char* name, const std::vector<Vec3>& set) {
    char buf[128];
    for (const Vec3& p : set) {
      std::snprintf(buf, sizeof buf, "%s %a %a %a\n", name, p.x, p.y, p.z);
      os << buf;
    }
  };
  points("a", c.a);
  points("b", c.b);
  return os.str();
}

PeerCase read_peer_case(const std::string& path) {
  InputFile in(path);
  PeerCase c;
  bool header = false;
  for (std::string line; in.next(line);) {
    const std::vector<std::string> w = words(line);
    if (w.empty() || w[0][0] == '#') continue;
    if (!header) {
      if (w.size() != 4 || w[0] != "peer" || (w[3] != "containment" && w[3] != "overlap"))
        throw InputError(
            path, in.line(),
            "expected `peer <library> <method> containment|overlap`, not " + quote(line));
      c.library = w[1], c.method = w[2], c.property = w[3];
      header = true;
    } else if (w[0] == "a" || w[0] == "b") {
      read_point(in, w, c);
    } else {
      throw InputError(path, in.line(), "expected a point `a|b x y z`, not " + quote(line));
    }
  }
  if (!header) throw InputError(path, 0, "no `peer` line");
  if (c.a.empty()) throw InputError(path, 0, "no point in set a");
  if ((c.property == "overlap") != !c.b.empty())
    throw InputError(path, 0,
                     c.property == "overlap" ? "an overlap case needs points in set b"
                                             : "a containment case has set a only");
  return c;
}

std::vector<std::string> list_peer_case_files(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return {};
  return files_below(dir, ".txt");
}

}  // namespace fdh::verify

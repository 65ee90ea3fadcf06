#include "fdh/gen/soup.hpp"

#include "draw.hpp"
#include "fdh/gen/rapidcheck.hpp"

namespace fdh::verify {
namespace {

Soup draw_soup(int max_tris) {
  Soup s;
  const int n = pick(1, max_tris);
  const auto coord = [] { return dyadic(-64, 64, 3); };
  const auto step = [] { return dyadic(-8, 8, 4); };
  for (int t = 0; t < n; ++t) {
    Tri tri;
    for (int& corner : tri) {
      if (!s.x0.empty() && pick(0, 3) == 3) {
        corner = pick(0, int(s.x0.size()) - 1);
      } else {
        corner = int(s.x0.size());
        const Vec3 p{coord(), coord(), coord()};
        s.x0.push_back(p);
        s.x1.push_back(p + Vec3{step(), step(), step()});
      }
    }
    s.tris.push_back(tri);
  }
  return s;
}

}  // namespace

rc::Gen<Soup> gen_soup(int max_tris) {
  return rc::gen::resize(rc::kNominalSize,
                         rc::gen::exec([max_tris] { return draw_soup(max_tris); }));
}

Soup generate_soup(int max_tris, std::uint64_t seed) {
  return gen_soup(max_tris)(rc::Random(seed)).value();
}

std::vector<std::vector<Vec3>> primitive_corners(const std::vector<Tri>& tris,
                                                 const std::vector<Vec3>& x0,
                                                 const std::vector<Vec3>& x1) {
  std::vector<std::vector<Vec3>> out;
  for (const Tri& t : tris) {
    std::vector<Vec3> pts;
    for (const int v : t) {
      pts.push_back(x0[v]);
      if (!x1.empty()) pts.push_back(x1[v]);
    }
    out.push_back(pts);
  }
  return out;
}

}  // namespace fdh::verify

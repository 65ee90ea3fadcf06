// FCL's k-DOPs (fcl/math/bv/kDOP.h): KDOP<double, N> for N = 16, 18, 24, built from points with
// operator+=, overlap by KDOP::overlap. FCL keeps N/2 minima then N/2 maxima; its slabs are the
// three axes, then getDistances<S, (N - 6) / 2>'s sums in their order (kDOP-inl.h): x+y, x+z,
// y+z, x-y, x-z (N = 16), y-z (N = 18), (x+y)-z, (x+z)-y, (y+z)-x (N = 24). The sums are
// rounded as FCL computes them and never pushed outward.
#include <fcl/config.h>

#include <fcl/math/bv/kDOP.h>

#include "fdh/peers/peers.hpp"

namespace fdh::verify {
namespace {

// FCL's slab directions, in its order.
const std::vector<Direction>& fcl_directions() {
  static const std::vector<Direction> all = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},
                                             {1, 0, 1},  {0, 1, 1},  {1, -1, 0}, {1, 0, -1},
                                             {0, 1, -1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  return all;
}

template <std::size_t N>
using Box = fcl::KDOP<double, N>;

template <std::size_t N>
Box<N> box_of(const double* lo, const double* hi) {
  Box<N> b;
  for (std::size_t s = 0; s < N / 2; ++s) b.dist(s) = lo[s], b.dist(s + N / 2) = hi[s];
  return b;
}

template <std::size_t N>
BoxMethod fcl_kdop() {
  BoxMethod m;
  m.name = "kdop" + std::to_string(N);
  m.summary = "fcl::KDOP<double, " + std::to_string(N) + ">, operator+= per point";
  m.k = int(N);
  m.directions.assign(fcl_directions().begin(), fcl_directions().begin() + N / 2);
  m.promise = Promise::None;
  m.build = [](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    Box<N> b;  // empty: +max below -max
    for (std::size_t i = 0; i < n; ++i) b += fcl::Vector3<double>(pts[i].x, pts[i].y, pts[i].z);
    for (std::size_t s = 0; s < N / 2; ++s) lo[s] = b.dist(s), hi[s] = b.dist(s + N / 2);
  };
  m.overlap = [](const double* la, const double* ha, const double* lb, const double* hb) {
    return box_of<N>(la, ha).overlap(box_of<N>(lb, hb));
  };
  return m;
}

}  // namespace

PeerLibrary fcl_library() {
  return {"fcl", FCL_VERSION, "double", {fcl_kdop<16>(), fcl_kdop<18>(), fcl_kdop<24>()}};
}

}  // namespace fdh::verify

#include "fdh/cloth/grid_springs.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fdh::cloth {

GridSprings::GridSprings(int grid, const std::vector<Vec3>& x, double k_structural, double k_shear,
                         double k_bend)
    : grid_(grid) {
  add_family(0, 1, k_structural, x);  // along rows
  add_family(1, 0, k_structural, x);  // along columns
  add_family(1, 1, k_shear, x);       // (r, c) to (r+1, c+1)
  add_family(1, -1, k_shear, x);      // (r, c+1) to (r+1, c)
  add_family(0, 2, k_bend, x);
  add_family(2, 0, k_bend, x);
}

void GridSprings::add_family(int dr, int dc, double k, const std::vector<Vec3>& x) {
  const int g = grid_, n = g * g;
  Family f{dr, dc, k, std::vector<double>(n, 0.0), {}, {}, {}};
  for (int r = 0; k > 0 && r + dr < g; ++r)
    for (int c = std::max(0, -dc); c < g - std::max(0, dc); ++c) {
      const int s = r * g + c;
      f.rest[s] = norm(x[s + dr * g + dc] - x[s]);
    }
  f.px.assign(pad() + n, 0.0), f.py = f.px, f.pz = f.px;
  families_.push_back(std::move(f));
}

namespace {

// The pulls of m springs from a[j] to b[j] (coordinates by array) into q, added to f: one run of
// a family. Plain arrays that overlap nowhere, so the loop runs on vector registers.
__attribute__((target_clones("avx2", "default"))) void run_pulls(
    int m, double k, const double* __restrict rest, const double* __restrict ax,
    const double* __restrict ay, const double* __restrict az, const double* __restrict bx,
    const double* __restrict by, const double* __restrict bz, double* __restrict qx,
    double* __restrict qy, double* __restrict qz, double* __restrict fx, double* __restrict fy,
    double* __restrict fz) {
  for (int j = 0; j < m; ++j) {
    const double dx = bx[j] - ax[j], dy = by[j] - ay[j], dz = bz[j] - az[j];
    const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    // A spring of length 0 has no direction: d = 0 makes its pull 0 (divided by 1, not 0).
    // len + (len == 0) is that divisor without a branch, so that the loop runs on vectors.
    const double q = k * (len - rest[j]) / (len + (len == 0));
    qx[j] = q * dx, qy[j] = q * dy, qz[j] = q * dz;
    fx[j] += q * dx, fy[j] += q * dy, fz[j] += q * dz;
  }
}

// f[j] -= q0[j], then q1[j], ... q5[j]: the six families' pulls on the particles where their
// springs end, one pass over f.
__attribute__((target_clones("avx2", "default"))) void subtract_six(
    int m, const double* __restrict q0, const double* __restrict q1, const double* __restrict q2,
    const double* __restrict q3, const double* __restrict q4, const double* __restrict q5,
    double* __restrict f) {
  for (int j = 0; j < m; ++j) f[j] = f[j] - q0[j] - q1[j] - q2[j] - q3[j] - q4[j] - q5[j];
}

}  // namespace

void GridSprings::start(const double* px, const double* py, const double* pz, double* fx,
                        double* fy, double* fz, int row_begin, int row_end) {
  const int g = grid_;
  for (Family& f : families_) {
    if (f.k <= 0) continue;  // the cloth has no such springs: its pulls stay 0
    const int offset = f.dr * g + f.dc, c0 = std::max(0, -f.dc), c1 = g - std::max(0, f.dc);
    double *qx = f.px.data() + pad(), *qy = f.py.data() + pad(), *qz = f.pz.data() + pad();
    for (int r = row_begin; r < std::min(row_end, g - f.dr); ++r) {
      const int s = r * g + c0, e = s + offset;
      run_pulls(c1 - c0, f.k, &f.rest[s], px + s, py + s, pz + s, px + e, py + e, pz + e, qx + s,
                qy + s, qz + s, fx + s, fy + s, fz + s);
    }
  }
}

void GridSprings::finish(double* fx, double* fy, double* fz, int row_begin, int row_end) const {
  const int g = grid_, i = row_begin * g, m = (row_end - row_begin) * g;
  // Where no spring of a family ends, the pull read is one of its zeros (padding, a particle
  // where none starts, or a family without springs): subtracting it changes nothing.
  const auto ends = [&](int f, std::vector<double> Family::*q) {
    return &(families_[f].*q)[pad() - (families_[f].dr * g + families_[f].dc) + i];
  };
  const std::pair<std::vector<double> Family::*, double*> coordinates[] = {
      {&Family::px, fx}, {&Family::py, fy}, {&Family::pz, fz}};
  for (const auto& [q, f] : coordinates)
    subtract_six(m, ends(0, q), ends(1, q), ends(2, q), ends(3, q), ends(4, q), ends(5, q), f + i);
}

}  // namespace fdh::cloth

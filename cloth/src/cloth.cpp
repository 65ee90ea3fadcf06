#include "fdh/cloth/cloth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fdh/cloth/parallel.hpp"

namespace fdh::cloth {

namespace {

int check_grid(int grid) {
  if (grid < 2) throw std::invalid_argument("a cloth needs at least 2×2 particles");
  return grid;
}

// Flat and level, row by row, centred on spec.centre.
std::vector<Vec3> rest_positions(const ClothSpec& spec) {
  const int g = spec.grid;
  const double spacing = spec.size / (g - 1);
  std::vector<Vec3> x(std::size_t(g) * g);
  for (int r = 0; r < g; ++r)
    for (int c = 0; c < g; ++c)
      x[std::size_t(r) * g + c] =
          spec.centre + Vec3{(c - (g - 1) / 2.0) * spacing, 0, (r - (g - 1) / 2.0) * spacing};
  return x;
}

}  // namespace

Cloth::Cloth(const ClothSpec& spec)
    : grid_(check_grid(spec.grid)),
      spec_(spec),
      x_(rest_positions(spec)),
      springs_by_family_(grid_, x_, spec.k_structural, spec.k_shear, spec.k_bend) {
  const int n = grid_ * grid_;
  m_ = spec.mass / n;
  spacing_ = spec.size / (grid_ - 1);
  v_.assign(n, Vec3{});
  pinned_.assign(n, 0);
  k_sum_.assign(n, 0);
  for (const auto& uv : spec.pins) {
    const int c = int(std::lround(std::clamp(uv[0], 0.0, 1.0) * (grid_ - 1)));
    const int r = int(std::lround(std::clamp(uv[1], 0.0, 1.0) * (grid_ - 1)));
    pinned_[index(r, c)] = 1;
  }
  for (int r = 0; r < grid_; ++r)
    for (int c = 0; c < grid_; ++c) {
      const int i = index(r, c);
      if (c + 1 < grid_) add_spring(i, index(r, c + 1), spec.k_structural);
      if (r + 1 < grid_) add_spring(i, index(r + 1, c), spec.k_structural);
      if (r + 1 < grid_ && c + 1 < grid_) {
        add_spring(i, index(r + 1, c + 1), spec.k_shear);
        add_spring(index(r, c + 1), index(r + 1, c), spec.k_shear);
        // (r, c) (r+1, c) (r+1, c+1) and (r, c) (r+1, c+1) (r, c+1): normals +y at rest.
        tris_.push_back({i, index(r + 1, c), index(r + 1, c + 1)});
        tris_.push_back({i, index(r + 1, c + 1), index(r, c + 1)});
        edges_.push_back({i, index(r + 1, c + 1)});
      }
      if (c + 2 < grid_) add_spring(i, index(r, c + 2), spec.k_bend);
      if (r + 2 < grid_) add_spring(i, index(r + 2, c), spec.k_bend);
      if (c + 1 < grid_) edges_.push_back({i, index(r, c + 1)});
      if (r + 1 < grid_) edges_.push_back({i, index(r + 1, c)});
    }
}

void Cloth::add_spring(int i, int j, double k) {
  if (k <= 0) return;
  springs_.push_back({i, j, norm(x_[j] - x_[i]), k});
  k_sum_[i] += k;
  k_sum_[j] += k;
}

// Rows per chunk: a cloth up to 64x64 is one chunk, run on the calling thread (waking other
// threads costs more than its whole step); larger ones are cut into chunks for every core.
constexpr int kParticleChunk = 1 << 12;

// Eqs. (1)–(3). Each particle's force is gravity and air, F = m·g - c·m·(v - wind), then its
// springs (GridSprings' order): the same sums in the same order for any chunks, so any threads.
void Cloth::integrate(double dt, std::vector<Vec3>& x_next) {
  const int n = this->n(), g = grid_, rows = std::max(1, kParticleChunk / g);
  x_next.resize(n);
  for (auto* a : {&px_, &py_, &pz_, &fx_, &fy_, &fz_}) a->resize(n);
  for_chunks(g, rows, [&](int r0, int r1) {
    for (int i = r0 * g; i < r1 * g; ++i) {
      px_[i] = x_[i].x, py_[i] = x_[i].y, pz_[i] = x_[i].z;
      const Vec3 f = m_ * spec_.gravity - (spec_.damping * m_) * (v_[i] - spec_.wind);
      fx_[i] = f.x, fy_[i] = f.y, fz_[i] = f.z;
    }
  });
  for_chunks(g, rows, [&](int r0, int r1) {
    springs_by_family_.start(px_.data(), py_.data(), pz_.data(), fx_.data(), fy_.data(), fz_.data(),
                             r0, r1);
  });
  const double h = dt / m_;  // Δt·a = Δt·F/m, eqs. (1)–(2)
  for_chunks(g, rows, [&](int r0, int r1) {
    springs_by_family_.finish(fx_.data(), fy_.data(), fz_.data(), r0, r1);
    for (int i = r0 * g; i < r1 * g; ++i) {
      if (pinned_[i]) {
        v_[i] = Vec3{};
        x_next[i] = x_[i];
        continue;
      }
      v_[i] += h * Vec3{fx_[i], fy_[i], fz_[i]};
      x_next[i] = x_[i] + dt * v_[i];  // eq. (3), with the new velocity
    }
  });
}

double Cloth::energy() const {
  double e = 0;
  for (int i = 0; i < n(); ++i) e += m_ * (0.5 * dot(v_[i], v_[i]) - dot(spec_.gravity, x_[i]));
  for (const Spring& s : springs_) {
    const double stretch = norm(x_[s.j] - x_[s.i]) - s.rest;
    e += 0.5 * s.k * stretch * stretch;
  }
  return e;
}

double Cloth::stable_dt() const {
  const double k = *std::max_element(k_sum_.begin(), k_sum_.end());
  return k > 0 ? std::sqrt(2 * m_ / k) : INFINITY;
}

double stable_dt(const ClothSpec& spec) {
  if (spec.grid < 2) return 0;
  const int g = spec.grid;
  // A particle's springs depend only on whether its row and its column are the first, second,
  // a middle, the second-to-last or the last: one candidate of each.
  const int cand[] = {0, 1, 2, g / 2, g - 3, g - 2, g - 1};
  const auto pos = [](double k) { return k > 0 ? k : 0.0; };
  double k_max = 0;
  for (const int r : cand)
    for (const int c : cand) {
      if (r < 0 || r >= g || c < 0 || c >= g) continue;
      const int rows = (r > 0) + (r + 1 < g), cols = (c > 0) + (c + 1 < g);
      const int bends = (r >= 2) + (r + 2 < g) + (c >= 2) + (c + 2 < g);
      const double k = (rows + cols) * pos(spec.k_structural) + rows * cols * pos(spec.k_shear) +
                       bends * pos(spec.k_bend);
      k_max = std::max(k_max, k);
    }
  const double m = spec.mass / (double(g) * g);
  return k_max > 0 ? std::sqrt(2 * m / k_max) : INFINITY;
}

}  // namespace fdh::cloth

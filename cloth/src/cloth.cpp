#include "fdh/cloth/cloth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fdh/cloth/parallel.hpp"

namespace fdh::cloth {

Cloth::Cloth(const ClothSpec& spec) : grid_(spec.grid), spec_(spec) {
  if (grid_ < 2) throw std::invalid_argument("a cloth needs at least 2×2 particles");
  const int n = grid_ * grid_;
  m_ = spec.mass / n;
  spacing_ = spec.size / (grid_ - 1);
  x_.resize(n);
  v_.assign(n, Vec3{});
  pinned_.assign(n, 0);
  k_sum_.assign(n, 0);
  for (int r = 0; r < grid_; ++r)
    for (int c = 0; c < grid_; ++c)
      x_[index(r, c)] = spec.centre + Vec3{(c - (grid_ - 1) / 2.0) * spacing_, 0,
                                           (r - (grid_ - 1) / 2.0) * spacing_};
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
  index_springs();
}

void Cloth::add_spring(int i, int j, double k) {
  if (k <= 0) return;
  springs_.push_back({i, j, norm(x_[j] - x_[i]), k});
  k_sum_[i] += k;
  k_sum_[j] += k;
}

void Cloth::index_springs() {
  const int n = this->n();
  incident_start_.assign(n + 1, 0);
  for (const Spring& s : springs_) ++incident_start_[s.i + 1], ++incident_start_[s.j + 1];
  for (int i = 0; i < n; ++i) incident_start_[i + 1] += incident_start_[i];
  incident_.resize(incident_start_[n]);
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (int s = 0; s < int(springs_.size()); ++s) {
    incident_[next[springs_[s].i]++] = 2 * s;
    incident_[next[springs_[s].j]++] = 2 * s + 1;
  }
  pull_.resize(2 * springs_.size());
}

// Chunk sizes: a cloth up to about 60x60 is one chunk of each, run on the calling thread (waking
// other threads costs more than its whole step); larger ones are cut into chunks for every core.
constexpr int kSpringChunk = 1 << 15, kParticleChunk = 1 << 12;

// Hooke: k·(|d| - rest)·d/|d| with d = x_j - x_i, each spring's pull on both its ends. (One
// pass: splitting it so that the square roots run on vector registers was slower, the extra
// passes over memory costing more than the square roots.)
void Cloth::spring_forces() {
  for_chunks(int(springs_.size()), kSpringChunk, [&](int begin, int end) {
    for (int s = begin; s < end; ++s) {
      const Spring& sp = springs_[s];
      const Vec3 d = x_[sp.j] - x_[sp.i];
      if (d == Vec3{}) {  // no direction to push along
        pull_[2 * s] = pull_[2 * s + 1] = Vec3{};
        continue;
      }
      const double len = std::sqrt(dot(d, d));
      const Vec3 f = (sp.k * (len - sp.rest) / (len == 0 ? 1.0 : len)) * d;
      pull_[2 * s] = f;
      pull_[2 * s + 1] = -f;  // exact: adding it is subtracting the pull
    }
  });
}

void Cloth::integrate(double dt, std::vector<Vec3>& x_next) {
  const int n = this->n();
  x_next.resize(n);
  if (int(springs_.size()) <= kSpringChunk && n <= kParticleChunk) {
    integrate_serial(dt, x_next);
    return;
  }
  spring_forces();
  const double h = dt / m_;  // Δt·a = Δt·F/m, eqs. (1)–(2)
  for_chunks(n, kParticleChunk, [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (pinned_[i]) {
        v_[i] = Vec3{};
        x_next[i] = x_[i];
        continue;
      }
      // Gravity and air: F = m·g - c·m·(v - wind); then the springs, in spring order.
      Vec3 f = m_ * spec_.gravity - (spec_.damping * m_) * (v_[i] - spec_.wind);
      for (int e = incident_start_[i]; e < incident_start_[i + 1]; ++e) f += pull_[incident_[e]];
      v_[i] += h * f;
      x_next[i] = x_[i] + dt * v_[i];  // eq. (3), with the new velocity
    }
  });
}

// The same sums in the same order (each particle's force, then its springs in spring order),
// scattered spring by spring: faster on one thread.
void Cloth::integrate_serial(double dt, std::vector<Vec3>& x_next) {
  const int n = this->n();
  force_.resize(n);
  for (int i = 0; i < n; ++i)  // gravity and air: F = m·g - c·m·(v - wind)
    force_[i] = m_ * spec_.gravity - (spec_.damping * m_) * (v_[i] - spec_.wind);
  for (const Spring& s : springs_) {  // Hooke: k·(|d| - rest)·d/|d|
    const Vec3 d = x_[s.j] - x_[s.i];
    if (d == Vec3{}) continue;  // no direction to push along
    const double len = std::sqrt(dot(d, d));
    const Vec3 f = (s.k * (len - s.rest) / (len == 0 ? 1.0 : len)) * d;
    force_[s.i] += f;
    force_[s.j] += -f;  // as the parallel path adds it
  }
  const double h = dt / m_;  // Δt·a = Δt·F/m, eqs. (1)–(2)
  for (int i = 0; i < n; ++i) {
    if (pinned_[i]) {
      v_[i] = Vec3{};
      x_next[i] = x_[i];
      continue;
    }
    v_[i] += h * force_[i];
    x_next[i] = x_[i] + dt * v_[i];  // eq. (3), with the new velocity
  }
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

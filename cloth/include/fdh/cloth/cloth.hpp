// Provot's mass–spring cloth as in Han & Jia 2013 §1: a square grid of particles joined by
// structural (grid neighbours), shear (diagonals) and bend (every second particle) springs,
// under gravity, air damping and an optional wind, integrated by the explicit Euler of
// eqs. (1)–(3) exactly as printed:
//   a = F / m (1),  v(t+Δt) = v(t) + Δt·a (2),  S(t+Δt) = S(t) + Δt·v(t+Δt) (3).
// (Updating the position with the new velocity makes this the symplectic Euler method.)
#pragma once

#include <array>
#include <stdexcept>
#include <vector>

#include "fdh/bvh.hpp"
#include "fdh/cloth/grid_springs.hpp"
#include "fdh/vec3.hpp"

namespace fdh::cloth {

struct ClothSpec {
  int grid = 25;              // particles per side
  double size = 1.6;          // side length at rest, m; the cloth starts flat and level
  Vec3 centre = {0, 1, 0};    // of the cloth at rest; it lies in the x–z plane
  double mass = 0.5;          // of the whole cloth, kg, shared equally by the particles
  double k_structural = 200;  // N/m
  double k_shear = 200;       // N/m
  double k_bend = 20;         // N/m
  double damping = 0.02;      // air: a force -damping·m·v, so a rate in 1/s
  Vec3 gravity = {0, -9.81, 0};
  Vec3 wind = {0, 0, 0};                    // air velocity, m/s: the damping pulls v towards it
  std::vector<std::array<double, 2>> pins;  // (u, v) in [0,1]²: the nearest particle is fixed
};

// Cloth::stable_dt() of the cloth `spec` makes, without building it (the grid's pattern of
// springs gives each particle's Σ_j k_ij); for checking a scene before a run.
double stable_dt(const ClothSpec& spec);

// A run whose positions or velocities left the finite range (kMaxMagnitude): thrown by
// Simulation::step() so that no inf or nan reaches an output. A std::runtime_error, so the CLI
// reports it with exit status 2.
class Diverged : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// |coordinate| of a position (m) or velocity (m/s) past which a run has diverged. A run within
// the scene ranges of docs/limits.md stays far below it, and every energy stays finite.
inline constexpr double kMaxMagnitude = 1e30;

struct Spring {
  int i, j;
  double rest, k;
};

class Cloth {
 public:
  explicit Cloth(const ClothSpec& spec);

  int n() const { return int(x_.size()); }
  int grid() const { return grid_; }
  int index(int row, int col) const { return row * grid_ + col; }
  const std::vector<Vec3>& x() const { return x_; }
  const std::vector<Vec3>& v() const { return v_; }
  std::vector<Vec3>& x() { return x_; }
  std::vector<Vec3>& v() { return v_; }
  const std::vector<Spring>& springs() const { return springs_; }
  bool pinned(int i) const { return pinned_[i]; }
  double particle_mass() const { return m_; }
  double spacing() const { return spacing_; }

  // Two triangles per grid cell, wound so that the normal points up (+y) at rest.
  const std::vector<Tri>& triangles() const { return tris_; }
  // The triangles' edges, each once: the grid lines and one diagonal per cell.
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }

  // Eqs. (1)–(3) for one step: new velocities into v(), and the positions they lead to into
  // `x_next` (x() is left as the start of the step, for the swept collision test). Each
  // particle sums its forces in one order (GridSprings'), whatever the thread count.
  void integrate(double dt, std::vector<Vec3>& x_next);

  // Kinetic + gravitational + spring energy, J.
  double energy() const;

  // The largest Δt for which eqs. (1)–(3) are linearly stable on this cloth: the symplectic
  // Euler step is stable while Δt·ω <= 2 for every mode ω, and by Gershgorin's theorem
  // ω² <= max_i 2·Σ_j k_ij / m (each spring's Hessian block has norm at most k while it is
  // stretched, as it is under gravity). So Δt <= sqrt(2m / max_i Σ_j k_ij).
  double stable_dt() const;

 private:
  void add_spring(int i, int j, double k);

  int grid_;
  double m_, spacing_;
  ClothSpec spec_;
  std::vector<Vec3> x_, v_;
  std::vector<char> pinned_;
  std::vector<Spring> springs_;
  GridSprings springs_by_family_;                    // the same springs, for the forces
  std::vector<double> px_, py_, pz_, fx_, fy_, fz_;  // positions and forces, by coordinate
  std::vector<double> k_sum_;                        // Σ_j k_ij per particle
  std::vector<Tri> tris_;
  std::vector<std::array<int, 2>> edges_;
};

}  // namespace fdh::cloth

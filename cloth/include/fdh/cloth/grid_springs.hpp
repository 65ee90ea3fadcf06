// The springs of a grid cloth, family by family: every spring of a family joins particle s to
// particle s + offset (structural along rows and columns, the two shear diagonals, bend along
// rows and columns), so a family is a few contiguous runs per row and its pulls are computed
// on positions stored coordinate by coordinate: loops the compiler runs on vector registers,
// square roots and divisions included (IEEE's correctly rounded operations either way, so the
// numbers are those of the one-spring-at-a-time loop).
#pragma once

#include <vector>

#include "fdh/vec3.hpp"

namespace fdh::cloth {

class GridSprings {
 public:
  // The springs of a grid × grid cloth at rest positions x (row-major); a family whose
  // stiffness is <= 0 has none, as the cloth leaves those springs out.
  GridSprings(int grid, const std::vector<Vec3>& x, double k_structural, double k_shear,
              double k_bend);

  // Hooke, k·(|d| - rest)·d/|d| with d = x_end - x_start (eq. (1)'s spring forces), added to
  // f{x,y,z} for the particles of rows [row_begin, row_end): first the pull of each family's
  // spring starting at the particle, family by family, then minus the pull of each family's
  // spring ending there. Two passes: start(...) on every row, then finish(...) on every row
  // (finish reads the pulls of springs that start up to two rows above). Each particle's sum
  // has the same order whatever rows a call covers, so chunks of rows can run on any thread.
  void start(const double* px, const double* py, const double* pz, double* fx, double* fy,
             double* fz, int row_begin, int row_end);
  void finish(double* fx, double* fy, double* fz, int row_begin, int row_end) const;

 private:
  struct Family {
    int dr, dc;                      // the end particle's row and column minus the start's
    double k;                        // stiffness, N/m
    std::vector<double> rest;        // per start particle (0 where none starts)
    std::vector<double> px, py, pz;  // the pull on the start particle, after pad() zeros
  };
  void add_family(int dr, int dc, double k, const std::vector<Vec3>& x);
  int pad() const { return 2 * grid_ + 2; }  // the largest offset, so ends never index below 0

  int grid_;
  std::vector<Family> families_;  // always six, in the constructor's order
};

}  // namespace fdh::cloth

// A point falls through a still triangle over the step: `robust` CCD (fast) and its exact twin
// (reference) both say "hit", and the twin gives the contact time; stopped short of the
// plane, both say "no".
#include <cstdio>

#include "fdh/ccd/robust.hpp"
#include "fdh/exact/ccd.hpp"

int main() {
  fdh::Query q;  // vertex-face: v f0 f1 f2 at t = 0, then at t = 1 (fdh/query.hpp)
  q.x = {fdh::Vec3{0.25, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
         fdh::Vec3{0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const bool hit = fdh::robust_ccd(q, fdh::exact::ccd_hit) && fdh::exact::ccd_hit(q);
  std::printf("falling through: hit at t = %s\n", fdh::exact::ccd(q).time_lo.c_str());
  q.x[4].z = 0.5;  // stops above the plane
  const bool miss = !fdh::robust_ccd(q, fdh::exact::ccd_hit) && !fdh::exact::ccd_hit(q);
  std::printf("stopping short: %s\n", miss ? "no contact" : "CONTACT (wrong)");
  return hit && miss ? 0 : 1;
}

// An fdhcert plug-in that wraps a real library (docs/plugins.md, "Wrapping a real library"):
// FCL 0.7's polynomial CCD, fcl::detail::Intersect<double>::intersect_VF and intersect_EE, as
// Debian's libfcl-dev ships them. It sees fdh/plugin.h and FCL's headers alone. FCL promises
// nothing exact (it solves the cubic in floating point, with interval Newton), so neither does
// the plug-in: certify measures it and fuzz stores where it is wrong.
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#include <fdh/plugin.h>

namespace {

using Intersect = fcl::detail::Intersect<double>;
using V = fcl::Vector3<double>;

V point(const double x[8][3], int i) {
  return V(x[i][0], x[i][1], x[i][2]);
}

// FCL's order is the triangle's corners a b c, then the vertex p (fdh's: v f0 f1 f2); each at
// t = 0, then at t = 1. Its time is 2 for no contact, else in [0, 1].
bool fcl_vertex_face(const double x[8][3], double* t) {
  V contact;
  return Intersect::intersect_VF(point(x, 1), point(x, 2), point(x, 3), point(x, 0), point(x, 5),
                                 point(x, 6), point(x, 7), point(x, 4), t, &contact);
}

// Edge a0b0 against edge c0d0: fdh's ea0 ea1 eb0 eb1, the same order.
bool fcl_edge_edge(const double x[8][3], double* t) {
  V contact;
  return Intersect::intersect_EE(point(x, 0), point(x, 1), point(x, 2), point(x, 3), point(x, 4),
                                 point(x, 5), point(x, 6), point(x, 7), t, &contact);
}

// No exception may cross the C interface: one from FCL or Eigen counts as "no contact", FCL's
// own answer when its solver gives up.
template <bool (*Fcl)(const double[8][3], double*)>
int verdict(const double x[8][3]) {
  try {
    double t = 2;
    return Fcl(x, &t) ? 1 : 0;
  } catch (...) {
    return 0;
  }
}

// FCL's time as a point enclosure [t, t]: no promise (FDH_TIME_NONE), measured as late or early.
// A time outside [0, 1] (NaN included) would be garbage to fdhcert; FCL's contract keeps it in
// [0, 1] on contact, and the clamp only guards that contract.
template <bool (*Fcl)(const double[8][3], double*)>
int time_of_impact(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;  // FCL's Newton iteration has its own tolerance
  try {
    double t = 2;
    if (!Fcl(x, &t)) return 0;
    t = t >= 0 ? (t <= 1 ? t : 1) : 0;
    *t_lo = *t_hi = t;
    return 1;
  } catch (...) {
    return 0;
  }
}

}  // namespace

// Intersect's functions are static and keep no state between calls (only constants), so
// certify and report may call them from every thread.
extern "C" unsigned fdh_plugin_flags(void) {
  return FDH_PLUGIN_THREAD_SAFE;
}

extern "C" const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = [] {
    fdh_plugin q{};
    q.abi_version = FDH_PLUGIN_ABI_VERSION;
    q.name = "fcl-ccd";
    q.summary = "FCL 0.7 polynomial CCD (Intersect<double>::intersect_VF, intersect_EE)";
    q.promise = FDH_PROMISE_NONE;                  // known to fail: measured, not certified
    q.vertex_face_ccd = verdict<fcl_vertex_face>;  // static queries too (point_triangle NULL)
    q.edge_edge_ccd = verdict<fcl_edge_edge>;
    q.time_promise = FDH_TIME_NONE;
    q.vertex_face_toi = time_of_impact<fcl_vertex_face>;
    q.edge_edge_toi = time_of_impact<fcl_edge_edge>;
    return q;
  }();
  return &p;
}

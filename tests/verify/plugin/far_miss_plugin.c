/* A plug-in of ABI version 2 that keeps its CONSERVATIVE promise near the unit scale only, for
   tests/verify/certify/test_certify_transforms.cpp: "no contact" where an axis parts the boxes
   of a query's two sides (exact: comparisons only, as the example plug-in), and also wherever
   a coordinate's magnitude exceeds 2^33, as a solver with an absolute tolerance might. No query
   certify draws is that large, so only the scales of the metamorphic stage can catch it. */
#include <fdh/plugin.h>
#include <math.h>

#define FAR 0x1p33

static void grow(double* lo, double* hi, double v) {
  if (v < *lo) *lo = v;
  if (v > *hi) *hi = v;
}
static int far_away(const double x[8][3]) {
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c)
      if (fabs(x[i][c]) > FAR) return 1;
  return 0;
}
/* 1 unless an axis parts the points of mask a (bit i: x[i]) from the others, or the query is
   far away. */
static int boxes_meet(const double x[8][3], unsigned a) {
  if (far_away(x)) return 0;
  for (int c = 0; c < 3; ++c) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 8; ++i) grow(&lo[(a >> i) & 1], &hi[(a >> i) & 1], x[i][c]);
    if (hi[0] < lo[1] || hi[1] < lo[0]) return 0;
  }
  return 1;
}
static int vertex_face(const double x[8][3]) {
  return boxes_meet(x, 0x11);
}
static int edge_edge(const double x[8][3]) {
  return boxes_meet(x, 0x33);
}
const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "far-miss",
                                      .summary = "axis-aligned boxes, blind beyond 2^33",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = vertex_face,
                                      .edge_edge_ccd = edge_edge};
  return &p;
}

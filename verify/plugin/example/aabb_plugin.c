/* An fdhcert plug-in (docs/plugins.md): "no contact" only when an axis parts the boxes of a
   query's two sides, which needs no rounding: a conservative method, in plain C. Its time of
   impact is the start of the step wherever the boxes meet: never late, however early. */
#include <fdh/plugin.h>
#include <math.h>

static void grow(double* lo, double* hi, double v) {
  if (v < *lo) *lo = v;
  if (v > *hi) *hi = v;
}
/* 1 unless an axis parts the points of mask a (bit i: x[i]) from the others. */
static int boxes_meet(const double x[8][3], unsigned a) {
  for (int c = 0; c < 3; ++c) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 8; ++i) grow(&lo[(a >> i) & 1], &hi[(a >> i) & 1], x[i][c]);
    if (hi[0] < lo[1] || hi[1] < lo[0]) return 0;
  }
  return 1;
}
/* The point's sweep p0 p1 (bits 0, 4) against the triangle's; edge e0 e1 against edge f0 f1. */
static int vertex_face(const double x[8][3]) {
  return boxes_meet(x, 0x11);
}
static int edge_edge(const double x[8][3]) {
  return boxes_meet(x, 0x33);
}
/* ABI version 2: the time of impact, [0, 1] for any contact the boxes allow. */
static int vertex_face_toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;
  *t_lo = 0, *t_hi = 1;
  return vertex_face(x);
}
static int edge_edge_toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;
  *t_lo = 0, *t_hi = 1;
  return edge_edge(x);
}
static void aabb(int k, const double (*p)[3], size_t n, double* lo, double* hi) {
  for (int c = 0; c < 3 && k == 6; ++c) {
    lo[c] = hi[c] = p[0][c];
    for (size_t i = 1; i < n; ++i) grow(&lo[c], &hi[c], p[i][c]);
  }
}
const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "aabb",
                                      .summary = "axis-aligned boxes",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = vertex_face,
                                      .edge_edge_ccd = edge_edge,
                                      .kdop_ks = FDH_KDOP_6,
                                      .kdop = aabb,
                                      .time_promise = FDH_TIME_NEVER_LATE,
                                      .vertex_face_toi = vertex_face_toi,
                                      .edge_edge_toi = edge_edge_toi};
  return &p;
}

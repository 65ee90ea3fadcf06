/* A plug-in of ABI version 2 whose time of impact is late on one query, for
   tests/verify/plugin/test_plugin.cpp: it promises never to be late, says contact at the start
   of the step everywhere (never late), except on a query whose point starts at x = MAGIC, where
   it says the end of the step. */
#include <fdh/plugin.h>

#define MAGIC 0.375 /* no probe query has it */

static int always(const double x[8][3]) {
  (void)x;
  return 1;
}

static int toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;
  *t_lo = x[0][0] == MAGIC ? 1 : 0;
  *t_hi = 1;
  return 1;
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "late-toi",
                                      .summary = "late on one query",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = always,
                                      .edge_edge_ccd = always,
                                      .time_promise = FDH_TIME_NEVER_LATE,
                                      .vertex_face_toi = toi,
                                      .edge_edge_toi = toi};
  return &p;
}

/* A plug-in of ABI version 2 with minimum-separation functions (fdh_plugin_min_distance), for
   tests/verify/plugin/test_plugin_min_distance.cpp: which function fdhcert calls at which δ, and
   which structs it refuses. Its contact functions say "no" (0) to every query; its δ functions
   say "hit" (1) at δ > 0 and answer 7, garbage, at δ = 0, where fdhcert must call the contact
   ones. Promise NONE: measured, never certified. Settings (fdh_plugin_init):
     missing=F      its δ struct leaves out F (vertex_face_ccd, edge_edge_ccd, vertex_face_toi,
                    edge_edge_toi) or, with missing=all, every function
     promise=N      the δ struct's promise is N (default 0), however wrong
     null=1         fdh_plugin_min_distance returns NULL */
#include <fdh/plugin.h>
#include <stdlib.h>
#include <string.h>

static struct fdh_min_distance within;
static int returns_null;

static int contact(const double x[8][3]) {
  (void)x;
  return 0;
}
static int contact_toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)x, (void)width, (void)t_lo, (void)t_hi;
  return 0;
}
static int at_delta(const double x[8][3], double delta) {
  (void)x;
  return delta > 0 ? 1 : 7;
}
static int at_delta_toi(const double x[8][3], double delta, double width, double* t_lo,
                        double* t_hi) {
  (void)width;
  *t_lo = 0, *t_hi = 1;
  return at_delta(x, delta);
}

const char* fdh_plugin_init(size_t n, const char* const* keys, const char* const* values) {
  within = (struct fdh_min_distance){0, NULL, at_delta, at_delta, 0, at_delta_toi, at_delta_toi};
  returns_null = 0;
  for (size_t i = 0; i < n; ++i) {
    const char* v = values[i];
    if (strcmp(keys[i], "promise") == 0)
      within.promise = atoi(v);
    else if (strcmp(keys[i], "null") == 0)
      returns_null = strcmp(v, "1") == 0;
    else if (strcmp(keys[i], "missing") != 0)
      return "keys: missing, promise, null";
    else if (strcmp(v, "vertex_face_ccd") == 0)
      within.vertex_face_ccd = NULL;
    else if (strcmp(v, "edge_edge_ccd") == 0)
      within.edge_edge_ccd = NULL;
    else if (strcmp(v, "vertex_face_toi") == 0)
      within.vertex_face_toi = NULL;
    else if (strcmp(v, "edge_edge_toi") == 0)
      within.edge_edge_toi = NULL;
    else if (strcmp(v, "all") == 0)
      within = (struct fdh_min_distance){0};
    else
      return "missing= takes a function's name or all";
  }
  return NULL;
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "min-distance-test",
                                      .promise = FDH_PROMISE_NONE,
                                      .vertex_face_ccd = contact,
                                      .edge_edge_ccd = contact,
                                      .time_promise = FDH_TIME_NONE,
                                      .vertex_face_toi = contact_toi,
                                      .edge_edge_toi = contact_toi};
  return &p;
}
const struct fdh_min_distance* fdh_plugin_min_distance(void) {
  return returns_null ? NULL : &within;
}

/* A plug-in of ABI version 2 that behaves as Tight Inclusion did when certified through a shim
   (issue 34, class 8), for tests/catalogue/test_slow_plugins.cpp: slow calls, a hang on one
   query, a time of 1e19 on another, and a time that is a lower bound only. Its verdicts are the
   boxes of the example plug-in (conservative, kept); its time is 0 with no upper bound
   (FDH_TIME_NO_UPPER_BOUND), never late. Settings (fdh_plugin_init):
     delay=SECONDS  each call sleeps that long first (default 0)
     hang=X         never returns on a query whose first point has x = X (both functions)
     huge=X         says contact at [1e19, 1e19] on a query whose first point has x = X
     once=1         fdh_plugin_flags says FDH_PLUGIN_TOI_GIVES_VERDICT (its time gives its verdict)
     count=PATH     each call appends a byte to PATH (the tests count the calls)
   A query with x = NaN matches nothing, the default. */
#include <fdh/plugin.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double delay, hang_x = NAN, huge_x = NAN;
static unsigned flags;
static char count_path[512];

static void sleep_for(double seconds) {
  struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
  while (nanosleep(&t, &t) != 0) {
  }
}

/* A slow call, and the hang: the library's solver that never ends on one query. */
static void enter(const double x[8][3]) {
  if (count_path[0]) {
    FILE* f = fopen(count_path, "a");
    if (f) fputc('.', f), fclose(f);
  }
  if (delay > 0) sleep_for(delay);
  if (x[0][0] == hang_x)
    for (;;) sleep_for(1);
}

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
static int vertex_face(const double x[8][3]) {
  enter(x);
  return boxes_meet(x, 0x11);
}
static int edge_edge(const double x[8][3]) {
  enter(x);
  return boxes_meet(x, 0x33);
}
/* A lower bound of t*: 0 wherever the boxes meet, no upper bound; 1e19 on the `huge` query.
   Its contact is the verdict's: the boxes' (one call of enter() for both). */
static int time_of(int hit, const double x[8][3], double* t_lo, double* t_hi) {
  *t_lo = x[0][0] == huge_x ? 1e19 : 0;
  *t_hi = x[0][0] == huge_x ? 1e19 : FDH_TIME_NO_UPPER_BOUND;
  return hit;
}
static int vertex_face_toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;
  return time_of(vertex_face(x), x, t_lo, t_hi);
}
static int edge_edge_toi(const double x[8][3], double width, double* t_lo, double* t_hi) {
  (void)width;
  return time_of(edge_edge(x), x, t_lo, t_hi);
}

/* A number with nothing after it. */
static int read_number(const char* text, double* out) {
  char* end = NULL;
  *out = strtod(text, &end);
  return end != text && *end == '\0';
}

const char* fdh_plugin_init(size_t n, const char* const* keys, const char* const* values) {
  static char why[200];
  delay = 0, hang_x = NAN, huge_x = NAN, flags = 0, count_path[0] = '\0';
  for (size_t i = 0; i < n; ++i) {
    double v = 0;
    const int ok = read_number(values[i], &v);
    if (ok && strcmp(keys[i], "delay") == 0 && v >= 0 && v <= 60)
      delay = v;
    else if (ok && strcmp(keys[i], "hang") == 0)
      hang_x = v;
    else if (ok && strcmp(keys[i], "huge") == 0)
      huge_x = v;
    else if (ok && strcmp(keys[i], "once") == 0 && (v == 0 || v == 1))
      flags = v == 1 ? FDH_PLUGIN_TOI_GIVES_VERDICT : 0;
    else if (strcmp(keys[i], "count") == 0 && strlen(values[i]) < sizeof count_path)
      strcpy(count_path, values[i]);
    else {
      snprintf(why, sizeof why,
               "cannot take %s=%s (it takes delay=0..60, hang=X, huge=X, once=0|1, count=PATH)",
               keys[i], values[i]);
      return why;
    }
  }
  return NULL;
}

unsigned fdh_plugin_flags(void) {
  return flags;
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "ti-like",
                                      .summary = "slow, hangs on one query, 1e19 on another",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = vertex_face,
                                      .edge_edge_ccd = edge_edge,
                                      .time_promise = FDH_TIME_NEVER_LATE,
                                      .vertex_face_toi = vertex_face_toi,
                                      .edge_edge_toi = edge_edge_toi};
  return &p;
}

/* A plug-in of ABI version 2 that takes settings (fdh_plugin_init) and declares flags
   (fdh_plugin_flags), for the settings and budget tests of
   tests/verify/plugin/test_plugin_settings.cpp. It says "hit" to every query (conservative: it
   misses no hit), unless told otherwise:
     delay=SECONDS     each call sleeps that long first (a slow library; default 0)
     answer=0          it says "no" to every query instead (and so breaks its promise)
     answer=2          it answers 2, garbage (the probe's child refuses it)
     thread_safe=1     fdh_plugin_flags declares FDH_PLUGIN_THREAD_SAFE
   Any other key, or a value it cannot read, is refused. tunable_threads_seen() counts the
   threads its query functions were called from since the last fdh_plugin_init. */
#include <fdh/plugin.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double delay;
static int answer = 1;
static unsigned flags;

static pthread_mutex_t seen_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_t seen[64];
static int seen_count;

int tunable_threads_seen(void) {
  pthread_mutex_lock(&seen_lock);
  const int n = seen_count;
  pthread_mutex_unlock(&seen_lock);
  return n;
}

static void note_thread(void) {
  const pthread_t self = pthread_self();
  pthread_mutex_lock(&seen_lock);
  int known = 0;
  for (int i = 0; i < seen_count; ++i) known |= pthread_equal(seen[i], self);
  if (!known && seen_count < 64) seen[seen_count++] = self;
  pthread_mutex_unlock(&seen_lock);
}

static int query(const double x[8][3]) {
  (void)x;
  note_thread();
  if (delay > 0) {
    struct timespec t = {(time_t)delay, (long)((delay - (double)(time_t)delay) * 1e9)};
    while (nanosleep(&t, &t) != 0) {
    }
  }
  return answer;
}

/* A number with nothing after it, in [lo, hi]. */
static int read_number(const char* text, double lo, double hi, double* out) {
  char* end = NULL;
  *out = strtod(text, &end);
  return end != text && *end == '\0' && *out >= lo && *out <= hi;
}

const char* fdh_plugin_init(size_t n, const char* const* keys, const char* const* values) {
  static char why[200];
  double v = 0;
  delay = 0, answer = 1, flags = 0, seen_count = 0;
  for (size_t i = 0; i < n; ++i) {
    if (strcmp(keys[i], "delay") == 0 && read_number(values[i], 0, 60, &v)) {
      delay = v;
    } else if (strcmp(keys[i], "answer") == 0 && read_number(values[i], 0, 2, &v)) {
      answer = (int)v;
    } else if (strcmp(keys[i], "thread_safe") == 0 && read_number(values[i], 0, 1, &v)) {
      flags = v == 1 ? FDH_PLUGIN_THREAD_SAFE : 0;
    } else {
      snprintf(why, sizeof why,
               "cannot take %s=%s (it takes delay=0..60, answer=0|1|2, "
               "thread_safe=0|1)",
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
                                      .name = "tunable",
                                      .summary = "says hit everywhere, as slowly as told",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = query,
                                      .edge_edge_ccd = query};
  return &p;
}

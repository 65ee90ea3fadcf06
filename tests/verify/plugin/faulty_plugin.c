/* Plug-ins that fail on purpose, one per FAULT, for tests/verify/plugin/test_plugin.cpp. Each
   answers 1 to every query (a conservative method) unless its fault says otherwise. */
#include <fdh/plugin.h>
#include <math.h>
#include <signal.h>

#define CRASH_WHEN_PROBED 1 /* vertex_face_ccd raises SIGSEGV on every call */
#define CRASH_ON_MAGIC 2    /* ... only on a query whose point starts at x = MAGIC */
#define GARBAGE_ON_MAGIC 3  /* vertex_face_ccd returns 7 there */
#define NAN_KDOP 4          /* the 6-DOP builder answers NaN */
#define WRONG_ABI 5         /* abi_version 99 */
#define TAKEN_NAME 6        /* calls itself "robust" */
#define BROKEN_PROMISE 7    /* promises exact answers, answers 0 */
#define LARGE_GARBAGE 8     /* vertex_face_ccd returns 7 where a point starts at |x| >= 1e20 */
#define PATH_NAME 9         /* calls itself ".." */
#define MAGIC 0.375         /* no probe query has it */

static int vertex_face(const double x[8][3]) {
  if (FAULT == CRASH_WHEN_PROBED || (FAULT == CRASH_ON_MAGIC && x[0][0] == MAGIC)) raise(SIGSEGV);
  if (FAULT == GARBAGE_ON_MAGIC && x[0][0] == MAGIC) return 7;
  if (FAULT == LARGE_GARBAGE && fabs(x[0][0]) >= 1e20) return 7;
  return FAULT == BROKEN_PROMISE ? 0 : 1;
}

static void kdop(int k, const double (*p)[3], size_t n, double* lo, double* hi) {
  (void)p, (void)n;
  for (int s = 0; s < k / 2; ++s) lo[s] = -1e300, hi[s] = FAULT == NAN_KDOP ? NAN : 1e300;
}

const struct fdh_plugin* fdh_plugin_v1(void) {
  static const struct fdh_plugin p = {
      .abi_version = FAULT == WRONG_ABI ? 99 : FDH_PLUGIN_ABI_VERSION,
      .name = FAULT == TAKEN_NAME  ? "robust"
              : FAULT == PATH_NAME ? ".."
                                   : NAME,
      .promise = FAULT == BROKEN_PROMISE ? FDH_PROMISE_EXACT : FDH_PROMISE_CONSERVATIVE,
      .vertex_face_ccd = vertex_face,
      .kdop_ks = FDH_KDOP_6,
      .kdop = kdop};
  return &p;
}

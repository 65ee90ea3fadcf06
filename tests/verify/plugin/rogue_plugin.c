/* Plug-ins that misbehave outside their answers, one per ROGUE, for the cage of
   tests/verify/plugin/test_plugin_cage.cpp (docs/plugins.md): each answers 1 to every query (a
   conservative method) unless its fault says otherwise. */
#include <fdh/plugin.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define CRASH_AT_LOAD 1 /* a constructor raises SIGSEGV */
#define EXIT_AT_LOAD 2  /* a constructor calls exit(0) */
#define EXIT_ON_200 3   /* the 200th call of this process calls exit(0) */
#define PRINTS 4        /* prints to standard output at load and on every call */
#define HANG_ON_MAGIC 5 /* never returns on a query whose point starts at x = MAGIC */
#define HANG_ON_300 6   /* never returns on the 300th call of this process (a fuzz worker's) */
#define MAGIC 0.375     /* no probe query has it */

__attribute__((constructor)) static void at_load(void) {
  if (ROGUE == CRASH_AT_LOAD) raise(SIGSEGV);
  if (ROGUE == EXIT_AT_LOAD) exit(0);
  if (ROGUE == PRINTS) printf("hello from the plug-in's constructor\n");
}

static int calls;

static int vertex_face(const double x[8][3]) {
  ++calls;
  if (ROGUE == EXIT_ON_200 && calls == 200) exit(0);
  if (ROGUE == HANG_ON_300 && calls == 300)
    for (;;) pause();
  if (ROGUE == PRINTS) {
    printf("printf from the plug-in\n");
    (void)!write(1, "write(1) from the plug-in\n", 26);
  }
  if (ROGUE == HANG_ON_MAGIC && x[0][0] == MAGIC)
    for (;;) pause();
  return 1;
}

static int edge_edge(const double x[8][3]) {
  (void)x;
  return 1;
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = NAME,
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = vertex_face,
                                      .edge_edge_ccd = edge_edge};
  return &p;
}

/* A plug-in of ABI version 2 that promises to be conservative and breaks it on one query, for
   the messages by promise (tests/verify/cli/test_promise_messages.cpp): it says hit everywhere (a
   false alarm wherever exact says no, which its promise allows) except on a query whose point
   starts at x = MAGIC, where it says no (a missed hit there breaks the promise). */
#include <fdh/plugin.h>

#define MAGIC 0.375 /* no probe query has it */

static int hit_but_magic(const double x[8][3]) {
  return x[0][0] != MAGIC;
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "miss-on-magic",
                                      .summary = "conservative but on one query",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .vertex_face_ccd = hit_but_magic,
                                      .edge_edge_ccd = hit_but_magic};
  return &p;
}

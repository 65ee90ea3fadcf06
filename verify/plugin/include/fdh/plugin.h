/* fdh/plugin.h: the C interface of fdhcert plug-ins, ABI version 2 (docs/plugins.md).
 *
 * A plug-in is a shared library that exports
 *
 *     const struct fdh_plugin* fdh_plugin_v2(void);
 *
 * returning a struct that lives as long as the library. A plug-in of ABI version 1 exports
 * fdh_plugin_v1 instead, with abi_version 1 and the struct up to kdop: it still loads, unchanged,
 * and gives no time of impact. `fdhcert classify|fuzz|replay|certify
 * --plugin lib.so` loads it and runs its functions like the built-in methods, against the
 * exact twin of each decision, under the promise it declares. It may also export
 * fdh_plugin_init (settings), fdh_plugin_flags (thread safety) and fdh_plugin_min_distance
 * (minimum separation), below. Plain C: it compiles
 * as C and as C++. */
#ifndef FDH_PLUGIN_H
#define FDH_PLUGIN_H

#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The value of fdh_plugin.abi_version this header describes. */
#define FDH_PLUGIN_ABI_VERSION 2

/* The value of abi_version of a plug-in of the first version (no time of impact). */
#define FDH_PLUGIN_ABI_VERSION_1 1

/* What fdhcert holds the query functions' answers to, against the exact answer. */
enum fdh_promise {
  FDH_PROMISE_NONE = 0,         /* measured, not promised: a wrong answer is counted, no more */
  FDH_PROMISE_CONSERVATIVE = 1, /* never 0 where the exact answer is 1 */
  FDH_PROMISE_EXACT = 2         /* the exact answer on every input */
};

/* A query: 8 points, x[i] = {x, y, z}, in the order of fdh::Query (fast/include/fdh/query.hpp):
 *   vertex-face: v f0 f1 f2, the vertex v and the triangle f0f1f2 at t = 0, then at t = 1,
 *                each vertex moving linearly;
 *   edge-edge:   ea0 ea1 eb0 eb1 at t = 0, then at t = 1 (the edges ea0ea1 and eb0eb1).
 * Return 1 for contact (closed sets: touching counts), 0 for none. Any other value is reported
 * as garbage and ends the run. */
typedef int (*fdh_query_fn)(const double x[8][3]);

/* The k-DOP of n >= 1 points (points[i] = {x, y, z}) for k = 6, 14, 18 or 26: k/2 slabs, lo[s]
 * <= hi[s], in fdh::Kdop<k>'s order (fast/include/fdh/kdop.hpp). Of the 13 directions
 *   0: (1,0,0)  1: (0,1,0)  2: (0,0,1)                                     axes
 *   3: (1,1,1)  4: (1,1,-1)  5: (1,-1,1)  6: (1,-1,-1)                     corners
 *   7: (1,1,0)  8: (1,-1,0)  9: (1,0,1)  10: (1,0,-1)  11: (0,1,1)  12: (0,1,-1)   edges
 * k = 6 takes 0-2, k = 14 takes 0-6, k = 18 takes 0-2 and 7-12, k = 26 all 13, in this order.
 * Slab s of a box bounds d.p over the points, d its direction (not normalised). fdhcert holds
 * every builder to containment: each slab must contain the exact extent of the points. A slab
 * with NaN, an infinity or lo > hi is garbage and ends the run. */
typedef void (*fdh_kdop_fn)(int k, const double (*points)[3], size_t n, double* lo, double* hi);

/* What fdhcert holds the time-of-impact functions' times to, against the exact earliest contact
 * time t* (ABI version 2). A late time (t_lo > t*, or a contact missed) breaks both promises. */
enum fdh_time_promise {
  FDH_TIME_NONE = 0,           /* measured, not promised */
  FDH_TIME_NEVER_LATE = 1,     /* no contact missed, and t_lo <= t* (early is allowed) */
  FDH_TIME_EXACT_ENCLOSURE = 2 /* the exact verdict, t_lo <= t* <= t_hi, t_hi - t_lo <= width */
};

/* The time of impact of a query (the 8 points as for fdh_query_fn): return 1 for contact, with
 * *t_lo <= *t_hi in [0, 1] enclosing the earliest contact time, asked no wider than `width`
 * (0 < width <= 1; a plug-in may ignore it); return 0 for none (t_lo and t_hi unread). A solver
 * advances to t_lo. A method that bounds t* from below only (FDH_TIME_NEVER_LATE) may set
 * *t_hi = FDH_TIME_NO_UPPER_BOUND: no upper bound, and no enclosure is read into it. Any other
 * return value is garbage and ends the run; a contact with t_lo, t_hi not in order in [0, 1]
 * is "not a time": a broken promise on that query, and the run goes on. */
typedef int (*fdh_toi_fn)(const double x[8][3], double width, double* t_lo, double* t_hi);

/* t_hi of a time with no upper bound (+infinity): a lower bound t_lo alone. Since ABI version 2
 * as it is (an infinite t_hi was refused before, so no plug-in gave one). */
#define FDH_TIME_NO_UPPER_BOUND HUGE_VAL

/* Bits of fdh_plugin.kdop_ks: the k the builder takes. */
#define FDH_KDOP_6 1u
#define FDH_KDOP_14 2u
#define FDH_KDOP_18 4u
#define FDH_KDOP_26 8u

struct fdh_plugin {
  int abi_version;     /* FDH_PLUGIN_ABI_VERSION */
  const char* name;    /* the method's name: a letter or digit, then up to 39 of a-z A-Z 0-9 . _
                          + -; not a built-in method's */
  const char* summary; /* one line for tables and certificates, or NULL */
  int promise;         /* an fdh_promise, for the three query functions */
  /* Any of these may be NULL: the method then makes no such decision (n/a). */
  fdh_query_fn point_triangle;  /* a still triangle (x[5..7] == x[1..3]): the segment p0p1
                                   against the triangle; when NULL, vertex_face_ccd decides */
  fdh_query_fn vertex_face_ccd; /* a moving point against a moving triangle over t in [0, 1] */
  fdh_query_fn edge_edge_ccd;   /* two moving edges over t in [0, 1] */
  unsigned kdop_ks;             /* FDH_KDOP_* bits; 0 when kdop is NULL */
  fdh_kdop_fn kdop;
  /* ABI version 2 only: a version-1 struct ends above, and fdhcert reads no further. */
  int time_promise;           /* an fdh_time_promise, for the two TOI functions */
  fdh_toi_fn vertex_face_toi; /* may be NULL: no time for vertex-face queries */
  fdh_toi_fn edge_edge_toi;   /* may be NULL: no time for edge-edge queries */
};

/* The entry point a plug-in exports: fdh_plugin_v2 (abi_version 2), or fdh_plugin_v1 for a
 * plug-in of ABI version 1 (abi_version 1; fdhcert looks for v2 first). */
const struct fdh_plugin* fdh_plugin_v2(void);
const struct fdh_plugin* fdh_plugin_v1(void);

/* Optional exports of either version, found by name (dlsym): a plug-in without them loads and
 * runs as before. fdhcert calls them once per load, in this order, before the entry point:
 *
 *   fdh_plugin_init(n, keys, values): the settings of `--plugin FILE:key=value,key2=value2`, in
 *     the order given (n = 0 without settings; keys unique, each non-empty; the strings live
 *     only during the call). Return NULL to accept them, or a string saying why not (it must
 *     stay valid until the next call into the plug-in: a string literal or a static buffer):
 *     fdhcert then stops with that reason and exit status 2. A plug-in that takes settings must
 *     export it; settings given to one that does not are refused the same way.
 *   fdh_plugin_flags(): FDH_PLUGIN_* bits, read after fdh_plugin_init.
 *
 * Both run in fdhcert's process and in its probing children (docs/plugins.md). */
typedef const char* (*fdh_plugin_init_fn)(size_t n, const char* const* keys,
                                          const char* const* values);
const char* fdh_plugin_init(size_t n, const char* const* keys, const char* const* values);

/* A bit of fdh_plugin_flags(): every function of the plug-in may be called from several threads
 * at once. fdhcert's checks then run on every core (--threads); without it, a loaded plug-in
 * keeps them on one thread. */
#define FDH_PLUGIN_THREAD_SAFE 1u

/* A bit of fdh_plugin_flags(): the contact its time-of-impact functions return (1 or 0) is its
 * verdict, the same question its query functions answer (a solver whose verdict is its time, as
 * Tight Inclusion's). `classify --toi` then calls the time function alone, once per query, and
 * takes the verdict from it. Without it, the two are asked apart. */
#define FDH_PLUGIN_TOI_GIVES_VERDICT 2u

typedef unsigned (*fdh_plugin_flags_fn)(void);
unsigned fdh_plugin_flags(void);

/* Minimum separation δ (issue 30; docs/plugins.md, "Minimum separation"): an optional export of
 * either version, found by name (dlsym) after the entry point,
 *
 *     const struct fdh_min_distance* fdh_plugin_min_distance(void);
 *
 * returning a struct that lives as long as the library. A query then also asks whether the
 * closed primitives come within Euclidean distance min_distance (a finite double >= 0, taken at
 * its exact value) at some t in [0, 1]; the earliest such t is the time asked. fdhcert calls these
 * functions on every query with min_distance > 0 (and at 0 where the plug-in has no contact
 * function of that decision); at 0 it calls the contact functions above, as before. A plug-in
 * without this export is n/a on every query with min_distance > 0.
 * The struct must give a verdict for every query decision the plug-in decides at contact
 * (point_triangle may be NULL: vertex_face_ccd then decides static queries), and a time for
 * every time the plug-in gives at contact; fdhcert refuses it otherwise. The method is held to
 * the weaker of its two promises (and of its two time promises) on every query. */
typedef int (*fdh_min_distance_fn)(const double x[8][3], double min_distance);
typedef int (*fdh_min_distance_toi_fn)(const double x[8][3], double min_distance, double width,
                                       double* t_lo, double* t_hi);

struct fdh_min_distance {
  int promise; /* an fdh_promise, against the exact Euclidean answer at min_distance */
  /* As the contact functions of struct fdh_plugin, with the minimum separation. */
  fdh_min_distance_fn point_triangle; /* may be NULL: vertex_face_ccd decides static queries */
  fdh_min_distance_fn vertex_face_ccd;
  fdh_min_distance_fn edge_edge_ccd;
  int time_promise; /* an fdh_time_promise, against the exact earliest time within min_distance */
  fdh_min_distance_toi_fn vertex_face_toi;
  fdh_min_distance_toi_fn edge_edge_toi;
};

typedef const struct fdh_min_distance* (*fdh_plugin_min_distance_fn)(void);
const struct fdh_min_distance* fdh_plugin_min_distance(void);

#ifdef __cplusplus
}
#endif

#endif /* FDH_PLUGIN_H */

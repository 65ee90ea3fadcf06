/* An fdhcert plug-in (docs/plugins.md, "Minimum separation") with the semantics of Tight
   Inclusion's minimum separation `ms` (Wang et al. 2021, "A Large-Scale Benchmark and an
   Inclusion-Based Algorithm for Continuous Collision Detection", sec. 5): a per-axis (L∞) test.
   It says "within δ" unless it proves that no t in [0, 1] has the L∞ distance between the closed
   primitives <= δ. The L∞ distance is at most the Euclidean one, so where the Euclidean distance
   is <= δ the L∞ one is too: a test that never misses an L∞ answer never misses a Euclidean one.
   It keeps FDH_PROMISE_CONSERVATIVE (its false alarms include every query whose L∞ distance comes
   within δ and its Euclidean distance does not, up to √3 δ apart) and FDH_TIME_NEVER_LATE (its
   time is at most the L∞ earliest time, itself at most the Euclidean one). At δ = 0 the two
   distances are 0 together, so the same test is a conservative contact test.

   How: F(t, u, v) = vertex - (a + u (b - a) + v (c - a)) (vertex-face, u, v >= 0, u + v <= 1) or
   (a + u (b - a)) - (c + v (d - c)) (edge-edge, u, v in [0, 1]), every point at time t. F is linear
   in each of t, u, v, so over a box of (t, u, v) its range is the hull of its 8 corner values
   (Tight Inclusion's inclusion function). A box is dropped only when that hull, widened by a
   bound on the rounding, misses the cube [-δ, δ]^3 on an axis, or lies past u + v = 1. */
#include <fdh/plugin.h>
#include <float.h>
#include <math.h>

/* A box of the parameters (t, u, v): lower corners and the halvings made in each. */
struct box {
  double lo[3];
  int depth[3];
};
/* At most kMaxBoxes boxes kept and kMaxSteps looked at: past either, "within" (no proof). */
enum { kMaxBoxes = 1024, kMaxSteps = 4000, kLeafDepth = 10 };

static double at(const double x[8][3], int i, int c, double t) {
  return x[i][c] + t * (x[i + 4][c] - x[i][c]);
}
/* F's coordinate c at (t, u, v). */
static double f(const double x[8][3], int vf, int c, double t, double u, double v) {
  const double a = at(x, vf ? 1 : 0, c, t), b = at(x, vf ? 2 : 1, c, t);
  const double p = at(x, vf ? 0 : 2, c, t), q = at(x, 3, c, t);
  if (vf) return p - a - u * (b - a) - v * (q - a);
  return a + u * (b - a) - (p + v * (q - p));
}
/* A bound on |computed F - exact F| at any (t, u, v) in [0, 1]^3 given M = the largest magnitude
   of a coordinate: about 51 units of roundoff times M (x(t) 5, each product term 14, the sums
   the rest), taken as 256 units (2^-45 M), with 2^-1060 for products that underflow. */
static double rounding(double m) {
  return m * 0x1p-45 + 0x1p-1060;
}
/* 0 when the box's F misses the cube [-delta, delta]^3 on an axis, widened by err. Else 1, and
   how much F changes along each parameter over the box (span[d], the largest over the corners
   and axes), which says where to halve it next. */
static int meets(const double x[8][3], int vf, const struct box* b, double delta, double err,
                 double span[3]) {
  double y[8][3];
  for (int k = 0; k < 8; ++k) {
    double p[3];
    for (int d = 0; d < 3; ++d)
      p[d] = b->lo[d] + ((k >> d) & 1 ? ldexp(1, -b->depth[d]) : 0); /* exact: dyadic */
    for (int c = 0; c < 3; ++c) y[k][c] = f(x, vf, c, p[0], p[1], p[2]);
  }
  span[0] = span[1] = span[2] = 0;
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 8; ++k) {
      lo = y[k][c] < lo ? y[k][c] : lo, hi = y[k][c] > hi ? y[k][c] : hi;
      for (int d = 0; d < 3; ++d)
        if ((k >> d) & 1) span[d] = fmax(span[d], fabs(y[k][c] - y[k ^ (1 << d)][c]));
    }
    if (lo - err > delta || hi + err < -delta) return 0;
  }
  return 1;
}
/* The parameter to halve: the one along which F changes most, of those not yet halved
   kLeafDepth times; -1 when none is left or F does not change along any (a leaf). */
static int to_halve(const struct box* b, const double span[3]) {
  int best = -1;
  for (int d = 0; d < 3; ++d)
    if (b->depth[d] < kLeafDepth && span[d] > 0 && (best < 0 || span[d] > span[best])) best = d;
  return best;
}

/* A min-heap of boxes by t (the earliest first): the first box found too small to split has
   the earliest t of every box left, so that t is never after the L∞ earliest time. Among boxes
   of the same t the deepest comes first, so that a hit is found depth first. */
struct heap {
  struct box b[kMaxBoxes];
  int n;
};
static int before(const struct box* a, const struct box* b) {
  if (a->lo[0] != b->lo[0]) return a->lo[0] < b->lo[0];
  return a->depth[0] + a->depth[1] + a->depth[2] > b->depth[0] + b->depth[1] + b->depth[2];
}
static void push(struct heap* h, struct box b) {
  int i = h->n++;
  for (; i > 0 && before(&b, &h->b[(i - 1) / 2]); i = (i - 1) / 2) h->b[i] = h->b[(i - 1) / 2];
  h->b[i] = b;
}
static struct box pop(struct heap* h) {
  const struct box top = h->b[0], last = h->b[--h->n];
  int i = 0;
  for (int c; (c = 2 * i + 1) < h->n; i = c) {
    if (c + 1 < h->n && before(&h->b[c + 1], &h->b[c])) ++c;
    if (!before(&h->b[c], &last)) break;
    h->b[i] = h->b[c];
  }
  h->b[i] = last;
  return top;
}

static double largest(const double x[8][3]) {
  double m = 0;
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) m = fabs(x[i][c]) > m ? fabs(x[i][c]) : m;
  return m;
}
/* Within delta in L∞ at some t? 1 with *t_lo <= the L∞ earliest time, unless it proved 0. */
static int within(const double x[8][3], int vf, double delta, double* t_lo) {
  struct heap h; /* on the stack: any thread may call (40 kB) */
  const double m = largest(x);
  *t_lo = 0;
  if (!(m <= 0x1p1000)) return 1; /* differences could overflow: no proof, so "within" */
  const double err = rounding(m);
  h.n = 0;
  push(&h, (struct box){{0, 0, 0}, {0, 0, 0}});
  for (int step = 0; h.n > 0; ++step) {
    struct box b = pop(&h);
    double span[3];
    if ((vf && b.lo[1] + b.lo[2] > 1) || !meets(x, vf, &b, delta, err, span)) continue;
    const int d = to_halve(&b, span);
    if (d < 0 || h.n + 2 > kMaxBoxes || step >= kMaxSteps) return *t_lo = b.lo[0], 1;
    b.depth[d] += 1; /* halve along d: the lower half, then the upper one */
    push(&h, b);
    b.lo[d] += ldexp(1, -b.depth[d]);
    push(&h, b);
  }
  return 0;
}

static int vertex_face_within(const double x[8][3], double delta) {
  double t;
  return within(x, 1, delta, &t);
}
static int edge_edge_within(const double x[8][3], double delta) {
  double t;
  return within(x, 0, delta, &t);
}
/* The time: t_lo never after the earliest time; t_hi 1, since the Euclidean earliest time may
   come after the L∞ one. `width` is not used. */
static int vertex_face_within_toi(const double x[8][3], double delta, double width, double* t_lo,
                                  double* t_hi) {
  (void)width;
  *t_hi = 1;
  return within(x, 1, delta, t_lo);
}
static int edge_edge_within_toi(const double x[8][3], double delta, double width, double* t_lo,
                                double* t_hi) {
  (void)width;
  *t_hi = 1;
  return within(x, 0, delta, t_lo);
}

const struct fdh_plugin* fdh_plugin_v2(void) {
  /* No contact functions: fdhcert calls the δ ones with δ = 0 for contact. */
  static const struct fdh_plugin p = {.abi_version = FDH_PLUGIN_ABI_VERSION,
                                      .name = "linf",
                                      .summary =
                                          "per-axis (L-infinity) minimum separation, as "
                                          "Tight Inclusion's ms",
                                      .promise = FDH_PROMISE_CONSERVATIVE,
                                      .time_promise = FDH_TIME_NEVER_LATE};
  return &p;
}
const struct fdh_min_distance* fdh_plugin_min_distance(void) {
  static const struct fdh_min_distance w = {.promise = FDH_PROMISE_CONSERVATIVE,
                                            .vertex_face_ccd = vertex_face_within,
                                            .edge_edge_ccd = edge_edge_within,
                                            .time_promise = FDH_TIME_NEVER_LATE,
                                            .vertex_face_toi = vertex_face_within_toi,
                                            .edge_edge_toi = edge_edge_within_toi};
  return &w;
}
unsigned fdh_plugin_flags(void) {
  return FDH_PLUGIN_THREAD_SAFE; /* no state: each call's boxes are on its own stack */
}

// The cloth against itself (optional, scene keyword `self_collision on`): after the obstacle
// response, every moving vertex–triangle and edge–edge pair of the cloth's own primitives that
// share no particle is tested over the step with `robust` CCD (fdh/ccd/robust.hpp) within the
// gap (the scene's self distance, fdh::Query::min_distance): whether its distance reaches the
// gap during the step.
//
// Candidates: the grid's patch tree (fdh/cloth/patch_tree.hpp), top down. A flat patch cannot
// touch itself over the step and is skipped whole (normal cones with the contour test, Volino &
// Magnenat-Thalmann 1994); otherwise each cell is tested on its own, and each pair of sibling
// patches tree against tree with swept FDHs (k-DOPs of the run's k) grown by half the gap.
//
// The gap of a pair: the scene's, unless the pair already lies within it at the start of the
// step (a float distance, fdh/cloth/pair_distance.hpp): then half of it, and within that half,
// contact. Such a pair would otherwise stop at once and stay stopped (docs/cloth.md, "The
// gap"). A pair near by construction, two of whose particles (one of each primitive) share a
// cell of the grid, is tested at contact and never repelled: it lies about 0.71 spacings apart
// at rest, close to the gap, and its springs keep it apart.
//
// Before the test, repulsion (Bridson, Fedkiw & Anderson 2002, §7.2, its inelastic part): a pair
// (not near by construction) within kRepelZone gaps at the start of the step whose closest
// points approach each other loses that approach, an impulse along the line between them shared
// by the pair's particles as their weights say; a particle in several such pairs takes their
// mean. It changes the velocities only (from the next step on: the step's end stays where the
// obstacle response left it), so that a layer resting on another hovers near the gap instead of
// meeting it in every step.
//
// Response, in three stages, each used only when the one before did not resolve the step:
// 1. rounds: the particles of every pair that reaches its gap stop at the pair's certified
//    earliest time there, at rest: robust's t_lo (fdh/ccd/toi.hpp, never after it; the start of
//    the step when it is 0), the earliest of a particle's pairs; the test runs again on the
//    shortened motion (new pairs can appear with neighbours that kept moving), up to kRounds
//    rounds; then, up to kStartRounds more, the particles of pairs still within their gap go
//    back to the start of the step, at rest (the start keeps every pair at rest out of its gap);
// 2. impact zones (Provot 1997; Bridson, Fedkiw & Anderson 2002): the particles of pairs still
//    within their gap are merged into zones (sets joined by those pairs, growing over the
//    iterations), and each zone moves as one rigid body for the step: it stays where the step
//    started and every particle of it takes the zone's mean velocity (momentum kept), up to
//    kZoneRounds iterations;
// 3. last resort: the whole cloth stays where the step started.
// Exact CCD (no false negatives; a gap >= 0 holds every contact) and an intersection-free start
// make the end of every step intersection-free, whatever stage ends it.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <vector>

#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"
#include "fdh/cloth/cloth.hpp"

namespace fdh::cloth {

class SelfCollision {
 public:
  static constexpr int kRounds = 4;
  static constexpr int kStartRounds = 4;
  static constexpr int kZoneRounds = 32;
  static constexpr double kRepelZone = 1.25;  // in gaps

  // k: the FDH's k. exact, exact_toi: robust's fallbacks for the verdict and the time of impact,
  // within a minimum separation (fdh::exact::ccd_hit and ccd_toi in this project). rounds: stage
  // 1's stops at the time (0 skips stage 1 whole, only to test stage 2). gap: the distance kept,
  // m (0: contact). dt: the step, s; 0 turns the repulsion off.
  SelfCollision(const Cloth& cloth, int k, CcdTest exact, ExactToi exact_toi, int rounds = kRounds,
                double gap = 0, double dt = 0);
  ~SelfCollision();

  struct Result {
    long repelled = 0;         // pairs the repulsion slowed
    long queries = 0;          // CCD queries run (after a round: those with a stopped particle)
    long hits = 0;             // of them, contacts
    int rounds = 0;            // rounds of stage 1 that stopped particles (both kinds)
    bool zones = false;        // stage 2 ran
    long zone_particles = 0;   // particles in impact zones at the end of stage 2
    bool stopped_all = false;  // stage 3 ran
    // Over the particles whose end of step the response changed: the lengths of their motions
    // summed, before the response and after it (kept / motion: how much of it was kept).
    double motion = 0, kept = 0;
    // The smallest distance at the end of the step among the pairs the last test looked at,
    // apart from those near by construction (float; infinite when none, or when stage 3 ran).
    // Pairs inside a patch that is flat over the step are not among them: they cannot touch,
    // but are not held apart.
    double min_distance = std::numeric_limits<double>::infinity();
  };

  // Makes the step from x0 to x free of self-contact, changing x and v where needed.
  Result resolve(const std::vector<Vec3>& x0, std::vector<Vec3>& x, std::vector<Vec3>& v);

  // One test of a candidate: its kind and its four particles (vf: v f0 f1 f2; ee: ea0 ea1 eb0 eb1).
  struct Candidate {
    QueryKind kind;
    std::array<int, 4> ids;
    double gap = 0;  // the pair's gap in the step, set by the test
  };

 private:
  struct Trees;
  template <int K>
  struct TreesK;
  // The contacts of the step x0 -> x (queries counted into r); search: find the candidates
  // again (false: the last search's still hold).
  void contacts(const std::vector<Vec3>& x0, const std::vector<Vec3>& x, Result& r,
                bool search = true);
  // The repulsion, on the velocities; the number of pairs it slowed.
  long repel(const std::vector<Vec3>& x0, std::vector<Vec3>& v);
  // Stage 1's later rounds: each particle of a pair still within its gap back at the start, at
  // rest.
  void stop_at_start(const std::vector<Vec3>& x0, std::vector<Vec3>& x, std::vector<Vec3>& v);
  // Stages 2 and 3 (v_in: the velocities before any stop, for the zones' means).
  void zone_stage(const std::vector<Vec3>& x0, std::vector<Vec3>& x, std::vector<Vec3>& v,
                  const std::vector<Vec3>& v_in, Result& r);
  // The three stages (resolve() adds the motion kept).
  Result stages(const std::vector<Vec3>& x0, std::vector<Vec3>& x, std::vector<Vec3>& v);
  // Stage 1's stop: each particle of a touching pair at rest at the earliest t_lo of its pairs.
  void stop_at_impact(const std::vector<Vec3>& x0, std::vector<Vec3>& x, std::vector<Vec3>& v);
  // The gap a pair is tested at, given its distance at the start of the step.
  double gap_of(double start_distance) const;
  // The smallest distance at x among the last test's candidates.
  double min_distance(const std::vector<Vec3>& x) const;

  const Cloth& cloth_;
  std::unique_ptr<Trees> trees_;
  CcdTest exact_;
  ExactToi exact_toi_;
  int rounds_;
  double gap_, dt_;
  std::vector<Candidate> candidates_, touching_;
  std::vector<Candidate>
      first_;  // the step's first search (with repulsion or not), for the measure
  std::vector<char> hit_;
  std::vector<double> toi_, stop_;  // per touching pair, per particle
  std::vector<Vec3> dv_;            // the repulsion's, per particle
  std::vector<int> count_;          // its pairs, per particle
  std::vector<char> changed_;       // per particle: stopped by the last round (empty: all)
};

}  // namespace fdh::cloth

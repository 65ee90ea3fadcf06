// The exact contact of a query's own decision (reference/): whether, where and when, for what
// shows it to people (classify's per-query CSV, fuzz's case files). The verdict is the twin's:
// exact::point_triangle and exact::ccd decide as twin_hit does (registry.hpp), and tell more.
#pragma once

#include <string>

#include "fdh/query.hpp"

namespace fdh::verify {

struct TwinContact {
  bool hit = false;
  // A static query's contact kind ("face", "edge", "vertex", "in-plane", "none"); "" for a
  // moving one, and for any query at δ > 0 (CCD gives no kind).
  std::string kind;
  // The earliest contact lies in [time_lo, time_hi], exact fractions ("p/q"), equal when the
  // time is rational (always for a static query); "" without a hit.
  std::string time_lo, time_hi;
  bool time_exact() const { return hit && time_lo == time_hi; }
};

TwinContact twin_contact(const Query& q);

// "hit (edge at t = 15/22)", "hit (at t = 1/2)", "hit (at t in [a, b])" or "no".
std::string contact_words(const TwinContact& c);

}  // namespace fdh::verify

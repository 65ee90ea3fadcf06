// Shrinking a failing case: greedy descent through RapidCheck's shrink tree, taking the first
// simpler value that still fails, until none does. Deterministic for a given tree.
#pragma once

#include <rapidcheck.h>

namespace fdh::verify {

template <class T, class Fails>
T shrink_failure(rc::Shrinkable<T> s, Fails fails, int max_evaluations = 20000) {
  for (bool improved = true; improved && max_evaluations > 0;) {
    improved = false;
    auto shrinks = s.shrinks();
    while (auto next = shrinks.next()) {
      if (--max_evaluations <= 0) break;
      if (fails(next->value())) {
        s = *next;
        improved = true;
        break;
      }
    }
  }
  return s.value();
}

}  // namespace fdh::verify

// The answer of a floating-point filter: certain yes, certain no, or uncertain (the caller's
// exact test decides). Shared by the static and the moving `robust` methods.
#pragma once

namespace fdh {

enum class Filtered { No, Yes, Uncertain };

// The filter's answer where it is certain, else exact().
template <class Exact>
inline bool or_exact(Filtered f, Exact&& exact) {
  return f == Filtered::Uncertain ? bool(exact()) : f == Filtered::Yes;
}

}  // namespace fdh

#include <stdexcept>

#include "fdh/ccd/robust.hpp"
#include "fdh/ccd/toi.hpp"

namespace fdh {

Toi robust_ccd_toi(const Query& q, double width, ExactToi exact_fallback) {
  if (!(width >= kMinToiWidth && width <= 1))
    throw std::invalid_argument("robust_ccd_toi: the width must lie in [2^-52, 1]");
  const FilteredToi f = robust_ccd_toi_filter(q, width);
  if (f.verdict == Filtered::No) return Toi{};
  if (f.enclosed) return {true, f.t0, f.t1};
  // The filter's window: no contact before t0, and with a certain contact, t* <= t1.
  return exact_fallback(q, f.t0, f.verdict == Filtered::Yes ? f.t1 : 1.0, width);
}

}  // namespace fdh

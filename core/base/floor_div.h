// Division rounded toward −∞ (C++'s / truncates toward zero): block and pixel indices of
// coordinates that may be negative (a target's box left of the frame, 1/256-px positions).
#pragma once
#include <stdint.h>

namespace qt {

// ⌊a / n⌋ for n >= 1 and any a (no overflow: −a is never formed for a < 0).
constexpr int64_t floor_div(int64_t a, int64_t n) { return a >= 0 ? a / n : -((n - 1 - a) / n); }

// a − n·⌊a / n⌋, in [0, n), for n >= 1.
constexpr int64_t floor_mod(int64_t a, int64_t n) { return a - floor_div(a, n) * n; }

}  // namespace qt

// Exact 64 × 64-bit products narrowed with rounding, for fixed-point steps whose operands are
// too wide for one int64 product (the Kalman filter's covariance and gains). No __int128: the
// product is built from 32-bit limbs, so it runs the same on Cortex-M.
#pragma once
#include <stdint.h>

namespace qt {

// round(a·b / 2^n), ties away from zero, saturated to ±(2^63 − 1); 0 <= n <= 126. The product
// is formed exactly in 128 bits from four 32×32 → 64-bit products (UMULL on Cortex-M), so
// there is no overflow for any int64 operands.
int64_t mul_shr_round(int64_t a, int64_t b, int n);

// 1/s for s > 0, as a 62-bit mantissa and an exponent:
//   m = round_half_up(2^(len+61) / s) ∈ [2^61, 2^62],  1/s = m·2^-(len+61)·(1 ± 2^-62),
// where s ∈ [2^(len-1), 2^len). One long division in 16-bit digits (four 32-bit divisions and
// their corrections; none of the precision a 32-bit divisor would lose), after which every
// ratio x/s is a 128-bit product exact to within its last bit.
struct Reciprocal {
    int64_t m;
    int len;
    // x/s with `frac` fraction bits, rounded half away: x·m·2^-(len+61-frac). Needs |x| <= 2^62
    // (the product stays below 2^124) and len + 61 - frac >= 0.
    int64_t ratio(int64_t x, int frac) const { return mul_shr_round(x, m, len + 61 - frac); }
};

// s > 0 and s < 2^63.
Reciprocal reciprocal(int64_t s);

}  // namespace qt

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

}  // namespace qt

// Integer square roots, bit by bit: shifts, adds and compares only, no division, no float.
#pragma once
#include <stdint.h>

namespace qt {

// floor(sqrt(n)) for every 32-bit n: the result r satisfies r*r <= n < (r+1)*(r+1).
uint16_t isqrt32(uint32_t n);

// floor(sqrt(n)) for every 64-bit n.
uint32_t isqrt64(uint64_t n);

// sqrt(n) rounded to nearest: floor(sqrt(n)) + 1 when n > r*r + r (the midpoint
// (r + 1/2)^2 = r^2 + r + 1/4 lies between integers, so there are no ties).
uint32_t isqrt64_round(uint64_t n);

}  // namespace qt

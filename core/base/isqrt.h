// Integer square roots, exact, in integers only (no float).
// constexpr, so compile-time capacities (hough.h) and run-time code share one definition.
#pragma once
#include <stdint.h>

namespace qt {

// floor(sqrt(n)) for every 32-bit n: the result r satisfies r*r <= n < (r+1)*(r+1). Newton's
// iteration x <- (x + n/x) / 2 in integers, from x = 2^ceil(bits/2) >= sqrt(n): it decreases
// until it reaches floor(sqrt(n)), the first x it does not decrease from (about five steps of
// one 32-bit division each, one UDIV on a Cortex-M3/M4, where the digits cost sixteen).
constexpr uint16_t isqrt32(uint32_t n) {
    if (n == 0) return 0;
    uint32_t x = uint32_t{1} << ((33 - __builtin_clz(n)) / 2);  // x <= 2^16: x + n/x < 2^17
    for (;;) {
        const uint32_t next = (x + n / x) / 2;
        if (next >= x) return static_cast<uint16_t>(x);
        x = next;
    }
}

// floor(sqrt(n)) for every 64-bit n; below 2^32, isqrt32. Above, the root's high bits are
// those of the root of n's top 32 bits (from an even shift 2h): r0·2^h <= sqrt(n) <
// (r0 + 1)·2^h; its h low bits follow one by one, each kept when the square stays within n
// (a 32 x 32 -> 64-bit product: the root is below 2^32).
constexpr uint32_t isqrt64(uint64_t n) {
    if ((n >> 32) == 0) return isqrt32(static_cast<uint32_t>(n));
    const int h = (65 - __builtin_clzll(n) - 32) / 2;  // n >> 2h < 2^32
    uint32_t r = static_cast<uint32_t>(isqrt32(static_cast<uint32_t>(n >> (2 * h)))) << h;
    for (int b = h - 1; b >= 0; --b) {
        const uint32_t t = r | (uint32_t{1} << b);
        if (static_cast<uint64_t>(t) * t <= n) r = t;
    }
    return r;
}

// sqrt(n) rounded to nearest: floor(sqrt(n)) + 1 when n > r*r + r (the midpoint
// (r + 1/2)^2 = r^2 + r + 1/4 lies between integers, so there are no ties). r + 1 can reach
// 2^32 only for n > 2^64 - 2^32; it saturates there.
constexpr uint32_t isqrt64_round(uint64_t n) {
    const uint64_t r = isqrt64(n);
    return static_cast<uint32_t>(n > r * r + r && r < 0xFFFFFFFFu ? r + 1 : r);
}

}  // namespace qt

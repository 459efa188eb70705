// Integer square roots, bit by bit: shifts, adds and compares only, no division, no float.
// constexpr, so compile-time capacities (hough.h) and run-time code share one definition.
#pragma once
#include <stdint.h>

namespace qt {

namespace detail {
// Digit-by-digit square root in base 4: `bit` walks down the even powers of two.
template <typename U>
constexpr U isqrt_bits(U n, U bit) {
    U root = 0;
    while (bit > n) bit >>= 2;
    while (bit != 0) {
        if (n >= root + bit) {
            n -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return root;
}
}  // namespace detail

// floor(sqrt(n)) for every 32-bit n: the result r satisfies r*r <= n < (r+1)*(r+1). The first
// digit is the highest even power of two <= n, found with a count of leading zeros (one CLZ on
// a Cortex-M3/M4).
constexpr uint16_t isqrt32(uint32_t n) {
    return n == 0 ? uint16_t{0}
                  : static_cast<uint16_t>(detail::isqrt_bits<uint32_t>(
                        n, uint32_t{1} << ((31 - __builtin_clz(n)) & ~1)));
}

// floor(sqrt(n)) for every 64-bit n; below 2^32 in 32-bit arithmetic (the same digits). Above,
// the root's high bits are those of the root of n's top 32 bits (from an even shift 2h):
// r0·2^h <= sqrt(n) < (r0 + 1)·2^h; its h low bits follow one by one, each kept when the
// square stays within n (a 32 x 32 -> 64-bit product: the root is below 2^32).
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

// A pseudo-random permutation of [0, n) with no memory, drawn one index at a time: a full-period
// linear congruential sequence over the smallest power of two 2^b >= n (every b-bit value once
// per period), each value scrambled by a b-bit bijection (xorshift, odd multiply, xorshift) so
// that successive indices land far apart, and values >= n skipped (fewer than half of them).
// About 15 instructions an index on a Cortex-M4. Keyed from the project PRNG: every platform
// visits the edge points in the same order for the same seed.
#pragma once
#include <stdint.h>

#include "base/prng.h"

namespace qt {

class VisitOrder {
public:
    VisitOrder(uint32_t n, uint64_t seed) : n_(n) {
        while ((1u << bits_) < n && bits_ < 31) ++bits_;
        mask_ = (1u << bits_) - 1u;
        shift_ = (bits_ + 1u) / 2u;
        Pcg32 rng(seed, 0x7669736974ULL);  // own stream: independent of other uses of `seed`
        state_ = rng.next() & mask_;
        increment_ = rng.next() | 1u;  // odd, with kMultiplier = 1 mod 4: the full period 2^b
    }

    // The next index of the order: n calls give each of 0 .. n - 1 once.
    uint32_t next() {
        uint32_t v;
        do {
            state_ = (state_ * kMultiplier + increment_) & mask_;
            v = state_ ^ (state_ >> shift_);
            v = (v * kScramble) & mask_;
            v ^= v >> shift_;
        } while (v >= n_);
        return v;
    }

private:
    static constexpr uint32_t kMultiplier = 0x2C9277B5u;  // = 1 mod 4
    static constexpr uint32_t kScramble = 0x9E3779B1u;    // odd: invertible modulo 2^b

    uint32_t n_;
    uint32_t bits_ = 1;
    uint32_t mask_ = 1;
    uint32_t shift_ = 1;
    uint32_t state_ = 0;
    uint32_t increment_ = 1;
};

}  // namespace qt

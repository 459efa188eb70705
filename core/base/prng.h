// The project's one pseudo-random generator: PCG32 (64-bit LCG state, xorshift-rotate output,
// M. O'Neill 2014). Integer-only, so x86-64, aarch64 and Cortex-M draw identical sequences
// from the same seed: PPHT point order, RANSAC samples, synthetic scenes and test vectors.
#pragma once
#include <stdint.h>

namespace qt {

class Pcg32 {
public:
    explicit constexpr Pcg32(uint64_t seed, uint64_t stream = 0x5851F42D4C957F2DULL)
        : state_(0), inc_((stream << 1) | 1u) {
        next();
        state_ += seed;
        next();
    }

    // Next 32 uniformly distributed bits.
    constexpr uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18) ^ old) >> 27);
        const uint32_t rot = static_cast<uint32_t>(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform integer in [0, n) for n >= 1, by multiply-and-shift (bias below n / 2^32).
    constexpr uint32_t below(uint32_t n) {
        return static_cast<uint32_t>((static_cast<uint64_t>(next()) * n) >> 32);
    }

private:
    uint64_t state_;
    uint64_t inc_;
};

}  // namespace qt

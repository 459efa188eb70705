// A pseudo-random permutation of [0, n) with no memory: a 4-round Feistel network on the
// smallest even number of bits covering n, keyed from the project PRNG, with cycle walking
// (re-apply until the value falls below n, which keeps it a bijection). PPHT visits edge
// points in this order, so every platform visits them in the same order for the same seed.
#pragma once
#include <stdint.h>

#include "base/prng.h"

namespace qt {

class VisitOrder {
public:
    VisitOrder(uint32_t n, uint64_t seed) : n_(n) {
        while ((1u << (2 * half_bits_)) < n && half_bits_ < 15) ++half_bits_;
        Pcg32 rng(seed, 0x7669736974ULL);  // own stream: independent of other uses of `seed`
        for (uint32_t& k : keys_) k = rng.next();
    }

    // The k-th index of the order, for k < n.
    uint32_t at(uint32_t k) const {
        uint32_t v = k;
        do v = permute(v);
        while (v >= n_);
        return v;
    }

private:
    uint32_t permute(uint32_t v) const {
        const uint32_t mask = (1u << half_bits_) - 1u;
        uint32_t left = v >> half_bits_, right = v & mask;
        for (uint32_t key : keys_) {
            // Round function: multiplicative hash of the keyed right half, top bits.
            const uint32_t f = ((right ^ key) * 0x9E3779B1u) >> (32 - half_bits_);
            const uint32_t next_right = (left ^ f) & mask;
            left = right;
            right = next_right;
        }
        return (left << half_bits_) | right;
    }

    uint32_t n_;
    uint32_t half_bits_ = 1;
    uint32_t keys_[4] = {};
};

}  // namespace qt

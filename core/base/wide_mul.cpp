#include "base/wide_mul.h"

#include "base/precondition.h"

namespace qt {

int64_t mul_shr_round(int64_t a, int64_t b, int n) {
    QT_PRECONDITION(n >= 0 && n <= 126);
    // Magnitudes as unsigned (two's-complement negation in uint64_t is defined, and gives 2^63
    // for INT64_MIN); the sign is applied at the end, so rounding half up on the magnitude is
    // rounding half away from zero on the signed value.
    const bool neg = (a < 0) != (b < 0);
    const uint64_t ua = a < 0 ? 0u - static_cast<uint64_t>(a) : static_cast<uint64_t>(a);
    const uint64_t ub = b < 0 ? 0u - static_cast<uint64_t>(b) : static_cast<uint64_t>(b);
    const uint64_t mask = 0xFFFFFFFFu;
    const uint64_t a0 = ua & mask, a1 = ua >> 32, b0 = ub & mask, b1 = ub >> 32;
    const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;  // each < 2^64
    const uint64_t mid = (p00 >> 32) + (p01 & mask) + (p10 & mask);             // < 3·2^32
    uint64_t lo = (mid << 32) | (p00 & mask);
    // hi < 2^64: the full product is < 2^126.
    uint64_t hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    if (n > 0) {  // + 2^(n-1): the half for rounding
        if (n - 1 < 64) {
            const uint64_t half = static_cast<uint64_t>(1) << (n - 1);
            lo += half;
            if (lo < half) ++hi;  // carry; hi stays < 2^64 (product + half < 2^127)
        } else {
            hi += static_cast<uint64_t>(1) << (n - 65);
        }
    }
    uint64_t q_lo, q_hi;
    if (n == 0) {
        q_lo = lo;
        q_hi = hi;
    } else if (n < 64) {
        q_lo = (lo >> n) | (hi << (64 - n));
        q_hi = hi >> n;
    } else {
        q_lo = hi >> (n - 64);
        q_hi = 0;
    }
    const uint64_t max = static_cast<uint64_t>(INT64_MAX);
    if (q_hi != 0 || q_lo > max) q_lo = max;
    const int64_t m = static_cast<int64_t>(q_lo);
    return neg ? -m : m;
}

namespace {

int bit_length(int64_t v) {  // v > 0: the n with 2^(n-1) <= v < 2^n
    return 64 - __builtin_clzll(static_cast<uint64_t>(v));
}

}  // namespace

Reciprocal reciprocal(int64_t s) {
    QT_PRECONDITION(s > 0);
    const int len = bit_length(s);  // len ∈ [1, 63]
    // m = round_half_up(2^(len+61) / s) = round_half_up(2^125 / d) with d = s·2^(64-len), whose
    // top bit is set: m = (r + 1) / 2 with r = floor(2^126 / d) ∈ (2^62, 2^63].
    const uint64_t d = static_cast<uint64_t>(s) << (64 - len);
    const uint64_t d_lo = d & 0xFFFFFFFFu, d_hi = d >> 32;
    const uint32_t d_top = static_cast<uint32_t>(d >> 48);  // >= 2^15
    // Long division of 2^62 · 2^64 by d in base-2^16 digits (Knuth's algorithm D): the
    // remainder rem < d throughout; each digit is estimated from the remainder's top 32 bits
    // and d's top 16 (one 32-bit division; the estimate is at most 2 above the digit).
    uint64_t rem = static_cast<uint64_t>(1) << 62;  // < d: the first digit is 0
    uint64_t r = 0;
    for (int k = 0; k < 4; ++k) {
        // rem·2^16 as a 16-bit top and 64 low bits, minus digit·d.
        uint32_t digit = static_cast<uint32_t>(rem >> 32) / d_top;
        if (digit > 0xFFFFu) digit = 0xFFFFu;
        const uint64_t p_lo = digit * d_lo, p_hi = digit * d_hi;  // each < 2^48
        const uint64_t low = rem << 16, sub = p_lo + (p_hi << 32);
        const uint64_t carry = sub < p_lo ? 1u : 0u;
        int64_t top = static_cast<int64_t>(rem >> 48) - static_cast<int64_t>((p_hi >> 32) + carry) -
                      (low < sub ? 1 : 0);
        uint64_t next = low - sub;
        while (top < 0) {  // the estimate was too big: add d back
            --digit;
            next += d;
            top += next < d ? 1 : 0;
        }
        rem = next;
        r = (r << 16) | digit;
    }
    return Reciprocal{static_cast<int64_t>((r + 1u) >> 1), len};
}

}  // namespace qt

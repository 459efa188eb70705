#include "target/ncc_match.h"

#include <stddef.h>

#include "base/isqrt.h"

namespace qt {

namespace {
// n·Σv² − (Σv)²: n² times the block's variance, grey levels²; 0 when the sums contradict
// Cauchy–Schwarz (they cannot for a real block).
uint64_t scaled_variance(uint32_t n, uint32_t sum, uint32_t sum_sq) {
    const uint64_t a = uint64_t{n} * sum_sq, b = uint64_t{sum} * sum;
    return a > b ? a - b : 0;
}
}  // namespace

bool ncc_flat(uint32_t n, uint32_t sum, uint32_t sum_sq, uint32_t min_variance) {
    const uint64_t v = scaled_variance(n, sum, sum_sq);
    return v == 0 || v < uint64_t{n} * n * min_variance;  // n <= 2^32, n² < 2^20 when valid
}

NccScore ncc_from_sums(const NccSums& s, uint32_t min_variance) {
    const NccScore none{0, true};
    if (s.n == 0 || s.n > kNccMaxPixels) return none;
    // Sums no real block of n pixels gives are refused; the bounds below rely on these.
    const uint32_t max_sum = 255 * s.n, max_sq = 65025 * s.n;
    if (s.sa > max_sum || s.sb > max_sum || s.saa > max_sq || s.sbb > max_sq || s.sab > max_sq)
        return none;
    if (ncc_flat(s.n, s.sa, s.saa, min_variance) || ncc_flat(s.n, s.sb, s.sbb, min_variance))
        return none;
    // |num| <= 2^36; va, vb in [1, 2^37) (< 2^34 for real blocks).
    const int64_t num = int64_t{s.n} * s.sab - int64_t{s.sa} * s.sb;
    uint64_t va = scaled_variance(s.n, s.sa, s.saa), vb = scaled_variance(s.n, s.sb, s.sbb);
    // sqrt(va·vb) = root · 2^(down − up). Halving both quarters the product: at most 5 steps
    // (2 for real blocks), after which both are still >= 2^22 (each was > 2^27 to overflow).
    int down = 0;
    while (va > UINT64_MAX / vb) {
        va >>= 1;
        vb >>= 1;
        ++down;
    }
    uint64_t p = va * vb;
    const int up = __builtin_clzll(p) / 2;  // p·4^up in [2^62, 2^64): a 32-bit root
    p <<= 2 * up;
    const uint64_t root = isqrt64(p);  // [2^31, 2^32)
    // q = round(32768·num / sqrt(va·vb)) = round(|num|·2^shift / root), shift in [10, 46].
    const int shift = 15 + up - down;
    const uint64_t mag = static_cast<uint64_t>(num < 0 ? -num : num);
    // Past `limit` the quotient exceeds 65536 (only for contradictory sums): saturate, and
    // below it mag·2^shift <= root·2^16 < 2^48.
    const uint64_t limit = (root << 16) >> shift;
    const uint64_t q = mag > limit ? 65536 : ((mag << shift) + root / 2) / root;
    if (num < 0)
        return {static_cast<int16_t>(q >= 32768 ? -32768 : -static_cast<int32_t>(q)), false};
    return {static_cast<int16_t>(q >= 32767 ? 32767 : q), false};
}

bool ncc_certainly_below(const NccSums& s, int32_t score_q15) {
    const int64_t num = int64_t{s.n} * s.sab - int64_t{s.sa} * s.sb;
    // n·Σab <= Σa·Σb: a score of 0 or below (refused and flat sums score 0 too).
    if (num <= 0) return score_q15 > 0;
    if (score_q15 < 5 || score_q15 > 32767 || s.n == 0 || s.n > kNccMaxPixels) return false;
    const uint64_t va = scaled_variance(s.n, s.sa, s.saa), vb = scaled_variance(s.n, s.sb, s.sbb);
    constexpr uint64_t kVarianceBound = uint64_t{1} << 34;
    if (va == 0 || vb == 0 || va >= kVarianceBound || vb >= kVarianceBound) return false;
    // 32768·num < b·sqrt(va·vb), b = score − 4, is 2^30·num² < b²·va·vb = x·vb (x = b²·va <
    // 2^64: b² < 2^30). num < 2^34, so with sh = its bits past 31 and m = num / 2^sh, rounded
    // up when anything is cut (m <= 2^31), num² <= m²·2^(2·sh), and it suffices that
    // m² <= x·vb / 2^(30 + 2·sh). That quotient is taken as (x / 2^s1)·vb / 2^s2, each step
    // rounded down (never above it), s1 the least shift that keeps the product in 64 bits:
    // about 30 significant bits either side, so only scores within a hair of b are left to
    // ncc_from_sums. When s2 would be negative, x·vb >= 2^(s1 + 62) puts the quotient at
    // 2^63 or more, above m².
    const uint64_t b = static_cast<uint64_t>(score_q15 - 4);
    const uint64_t x = b * b * va;
    const uint64_t mag = static_cast<uint64_t>(num);
    const int num_bits = 64 - __builtin_clzll(mag);
    const int sh = num_bits > 31 ? num_bits - 31 : 0;
    const uint64_t m = sh > 0 ? (mag >> sh) + 1u : mag;
    const int x_bits = 64 - __builtin_clzll(x), vb_bits = 64 - __builtin_clzll(vb);
    const int s1 = x_bits + vb_bits > 64 ? x_bits + vb_bits - 64 : 0;
    const int s2 = 30 + 2 * sh - s1;
    if (s2 < 0) return true;
    const uint64_t low = s2 >= 64 ? 0u : ((x >> s1) * vb) >> s2;
    return m * m <= low;
}

NccScore ncc_q15(const uint8_t* a, uint32_t a_stride, const uint8_t* b, uint32_t b_stride,
                 uint16_t w, uint16_t h, uint32_t min_variance) {
    NccSums s;
    s.n = uint32_t{w} * h;
    if (s.n == 0 || s.n > kNccMaxPixels) return {0, true};
    // 32-bit sums: n <= 1024 bounds them by 2^18 and 2^26 (header).
    for (uint16_t y = 0; y < h; ++y)
        ncc_add_row<true>(a + size_t{y} * a_stride, b + size_t{y} * b_stride, w, s);
    return ncc_from_sums(s, min_variance);
}

// The matcher at the QVGA configuration, so that the library build and the float-free check
// compile the template.
template uint16_t match_features<4, 96, 96>(const FeatureSet<4, 96>&, const FeatureSet<4, 96>&,
                                            const MatchParams&, FeatureMatch*, uint16_t,
                                            MatchStats*);

}  // namespace qt

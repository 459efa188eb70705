// Zero-mean normalised cross-correlation of grey-level blocks in Q15, and matching of two
// frames' Harris corners by the NCC of their patches (the Filtering and Geometry paper, Table I,
// step 2). Integer only.
//
// For n = w·h pixels with sums Sa = Σa, Sb = Σb, Saa = Σa², Sbb = Σb², Sab = Σab:
//   ncc = (n·Sab − Sa·Sb) / sqrt((n·Saa − Sa²)·(n·Sbb − Sb²))  ∈ [−1, 1]
//   q15 = round(32768·ncc) clamped to [−32768, 32767]
// Bounds: n <= kNccMaxPixels = 1024, so Sa <= 2^18, Saa and Sab <= 1024·255² < 2^27 (32-bit
// sums); the variance terms n·Saa − Sa² are n²·σ² <= 2^20·127.5² < 2^34 and their product
// < 2^68, computed in 64 bits with a 2-bit pre-shift when it would overflow; the root is
// taken of that product normalised to [2^62, 2^64) (32 significant bits), so q15 is within
// 1 of round(32768·ncc).
#pragma once
#include <stdint.h>
#include <string.h>

#if defined(__ARM_FEATURE_SIMD32)
#include <arm_acle.h>
#endif

#include "base/setting_range.h"
#include "target/feature.h"

namespace qt {

constexpr uint32_t kNccMaxPixels = 1024;  // e.g. 32×32; bounds every sum above
// Flat block: n·Σa² − (Σa)² < n²·min_variance, i.e. variance below min_variance grey levels²
// per pixel. 4 = a standard deviation of 2 grey levels, about a camera's noise: such a block
// has no structure to correlate.
constexpr uint32_t kNccMinVariance = 4;

// q15: 32767 ≈ +1, −32768 = −1. flat: either block is flat (or the size is 0 or above
// kNccMaxPixels): q15 = 0, no division made.
struct NccScore {
    int16_t q15;
    bool flat;
};

// The sums over a pair of blocks, for callers that keep some of them (a template's Σa, Σa²
// are the same at every search position).
struct NccSums {
    uint32_t n = 0;  // pixels, <= kNccMaxPixels
    uint32_t sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
};

#if defined(__ARM_FEATURE_SIMD32)
namespace detail {
// Four bytes as two pairs of halfwords, bytes 0 and 2 (even) and bytes 1 and 3 (odd): one
// UXTB16 each, the odd one with its ROR 8 folded in. `four` keeps the bytes as loaded.
struct BytePairs {
    uint32_t four;
    int16x2_t even, odd;
};
inline BytePairs pairs_of(uint32_t four) {
    BytePairs b;
    b.four = four;
    b.even = static_cast<int16x2_t>(__uxtb16(four));
    b.odd = static_cast<int16x2_t>(__uxtb16((four >> 8) | (four << 24)));
    return b;
}
inline BytePairs byte_pairs(const uint8_t* p) {
    uint32_t four;
    memcpy(&four, p, 4);
    return pairs_of(four);
}
// acc + the four products of a's and b's bytes: two SMLAD.
inline int32_t add_products(const BytePairs& a, const BytePairs& b, int32_t acc) {
    return __smlad(a.odd, b.odd, __smlad(a.even, b.even, acc));
}
}  // namespace detail
#endif

// Σ a[i]·b[i] over n <= kNccMaxPixels bytes (below 2^27).
inline uint32_t dot_bytes(const uint8_t* a, const uint8_t* b, uint32_t n) {
    uint32_t i = 0;
    uint32_t d = 0;
#if defined(__ARM_FEATURE_SIMD32)
    // Four bytes a step on a Cortex-M4 (the sum stays below 2^31: the loop's value).
    int32_t acc = 0;
    for (; i + 4u <= n; i += 4u)
        acc = detail::add_products(detail::byte_pairs(a + i), detail::byte_pairs(b + i), acc);
    d = static_cast<uint32_t>(acc);
#endif
    for (; i < n; ++i) d += uint32_t{a[i]} * b[i];
    return d;
}

// Σ a·b over a w × h block: a's rows packed (w bytes apart), b's `stride` bytes apart (below
// 2^27, n <= kNccMaxPixels). On a Cortex-M4 each row goes four bytes a step, and a row whose
// width is not a multiple of four (w >= 4) ends with one more step on its last four bytes, a's
// bytes already counted masked to 0: no byte-by-byte tail, and nothing read outside the rows.
// The same sum as dot_bytes row by row.
inline uint32_t dot_block(const uint8_t* a, uint32_t w, uint32_t h, const uint8_t* b,
                          uint32_t stride) {
#if defined(__ARM_FEATURE_SIMD32)
    if (w >= 4u) {
        const uint32_t steps = w / 4u, rest = w % 4u;
        // The last step's a word: its first 4 − rest bytes (counted already) cleared.
        const uint32_t keep = rest == 0u ? 0u : ~0u << (8u * (4u - rest));
        int32_t acc = 0;
        for (uint32_t y = 0; y < h; ++y, a += w, b += stride) {
            for (uint32_t k = 0; k < steps; ++k)
                acc = detail::add_products(detail::byte_pairs(a + 4u * k),
                                           detail::byte_pairs(b + 4u * k), acc);
            if (rest != 0u) {
                uint32_t last;
                memcpy(&last, a + w - 4u, 4);
                acc = detail::add_products(detail::pairs_of(last & keep),
                                           detail::byte_pairs(b + w - 4u), acc);
            }
        }
        return static_cast<uint32_t>(acc);
    }
#endif
    uint32_t d = 0;
    for (uint32_t y = 0; y < h; ++y, a += w, b += stride) d += dot_bytes(a, b, w);
    return d;
}

// Adds one row of w pixels of blocks a and b to the sums: Σb, Σb², Σab, and with WithA also
// Σa, Σa² (a template's, summed once by its caller otherwise). n is the caller's.
template <bool WithA>
inline void ncc_add_row(const uint8_t* a, const uint8_t* b, uint32_t w, NccSums& s) {
    uint32_t x = 0;
#if defined(__ARM_FEATURE_SIMD32)
    // Four pixels a step on a Cortex-M4: USADA8 adds four bytes, SMLAD multiplies and adds
    // two pairs. Every sum stays below 2^31 (header), so the signed accumulations give the
    // loop's values.
    uint32_t sa = s.sa, sb = s.sb;
    int32_t saa = static_cast<int32_t>(s.saa), sbb = static_cast<int32_t>(s.sbb),
            sab = static_cast<int32_t>(s.sab);
    for (; x + 4u <= w; x += 4u) {
        const detail::BytePairs pa = detail::byte_pairs(a + x), pb = detail::byte_pairs(b + x);
        if (WithA) {
            sa = __usada8(pa.four, 0u, sa);
            saa = detail::add_products(pa, pa, saa);
        }
        sb = __usada8(pb.four, 0u, sb);
        sbb = detail::add_products(pb, pb, sbb);
        sab = detail::add_products(pb, pa, sab);
    }
    s.sa = sa;
    s.sb = sb;
    s.saa = static_cast<uint32_t>(saa);
    s.sbb = static_cast<uint32_t>(sbb);
    s.sab = static_cast<uint32_t>(sab);
#endif
    for (; x < w; ++x) {
        const uint32_t va = a[x], vb = b[x];
        if (WithA) {
            s.sa += va;
            s.saa += va * va;
        }
        s.sb += vb;
        s.sbb += vb * vb;
        s.sab += va * vb;
    }
}

// True when n·sum_sq − sum² < n²·min_variance, or == 0 (for any min_variance); n <= kNccMaxPixels.
bool ncc_flat(uint32_t n, uint32_t sum, uint32_t sum_sq, uint32_t min_variance);

// The score from the sums: one 64-bit square root (isqrt64) and one 64-bit division.
NccScore ncc_from_sums(const NccSums& s, uint32_t min_variance = kNccMinVariance);

// True only when ncc_from_sums(s, ·).q15 < score_q15 (any min_variance): for a search that needs
// to know whether a candidate can beat its best, without the root and the division (a few
// 32 × 32 → 64-bit products). A score of 0 or below (ncc <= 0) is below any positive one;
// otherwise it tests 32768·ncc < score_q15 − 4, which q15 (within 1 of round(32768·ncc)) then
// also satisfies, in 64 bits with bounds that err towards false: false when score_q15 < 5 or
// a block's variance term n·Σv² − (Σv)² is 0 or not below 2^34 (no real block of
// kNccMaxPixels pixels reaches it).
bool ncc_certainly_below(const NccSums& s, int32_t score_q15);

// w×h blocks at a and b (row strides in bytes).
NccScore ncc_q15(const uint8_t* a, uint32_t a_stride, const uint8_t* b, uint32_t b_stride,
                 uint16_t w, uint16_t h, uint32_t min_variance = kNccMinVariance);

struct MatchParams {
    uint16_t search_radius_px = 24;      // |cur − (prev + offset)| <= this in x and y each, px
    int16_t offset_x = 0, offset_y = 0;  // expected displacement prev → cur, px
    int16_t min_score_q15 = 26214;       // 0.8
    bool mutual = true;                  // keep a pair only when each is the other's best
    // Best − second best score of a prev corner's candidates, Q15; 1638 ≈ 0.05: a repeated
    // pattern gives two near-equal bests and is refused; a lone candidate passes.
    int16_t min_margin_q15 = 1638;
    uint32_t min_variance = kNccMinVariance;  // flat patches never match (see above)
};

// MatchParams' units and accepted ranges (base/setting_range.h); the score in NCC, -1..1.
struct MatchRanges {
    SettingRange search_radius_px{"px", 1, 128};
    SettingRange min_score{"", -1, 1};
};
inline constexpr MatchRanges kMatchRanges{};

struct FeatureMatch {
    uint16_t prev, cur;  // indices into the two sets
    int16_t score_q15;
};

// Each prev corner lands in exactly one of: flat, no_candidate, below_min, ambiguous,
// not_mutual, dropped_capacity, or the output.
struct MatchStats {
    uint32_t scored = 0;  // pairs whose NCC was computed (both non-flat, within the window)
    uint16_t flat = 0, no_candidate = 0, below_min = 0, ambiguous = 0, not_mutual = 0,
             dropped_capacity = 0;
};

namespace detail {
struct PatchSums {
    uint32_t sum, sum_sq;
    bool flat;
};
template <int R>
PatchSums patch_sums(const Feature<R>& f, uint32_t min_variance) {
    uint32_t s = 0, ss = 0;  // <= 225·255 and 225·255²
    for (int i = 0; i < Feature<R>::kSide * Feature<R>::kSide; ++i) {
        s += f.patch[i];
        ss += uint32_t{f.patch[i]} * f.patch[i];
    }
    return {s, ss, ncc_flat(Feature<R>::kSide * Feature<R>::kSide, s, ss, min_variance)};
}
template <int R>
uint32_t patch_dot(const Feature<R>& a, const Feature<R>& b) {
    return dot_bytes(a.patch, b.patch, Feature<R>::kSide * Feature<R>::kSide);
}
}  // namespace detail

// Matches prev's corners to cur's by the NCC of their patches: for each prev corner, the best
// non-flat cur corner within the search window (first index on ties), kept when its score
// >= min_score, beats the second best by min_margin and, if mutual, prev is also that cur
// corner's best (first index on ties) among the prev corners whose window holds it. Work:
// one patch dot product per pair in the window, |prev|·|cur| at most; stack: about
// 22·N1 + 18·N2 bytes (4 KB at 96 + 96). Output in prev order, up to `capacity`; returns the number
// written.
template <int R, uint16_t N1, uint16_t N2>
uint16_t match_features(const FeatureSet<R, N1>& prev, const FeatureSet<R, N2>& cur,
                        const MatchParams& config, FeatureMatch* out, uint16_t capacity,
                        MatchStats* stats = nullptr) {
    constexpr uint32_t kN = Feature<R>::kSide * Feature<R>::kSide;
    constexpr uint16_t kNone = 0xFFFF;
    constexpr int32_t kNoScore = INT32_MIN;  // below every Q15 score
    static_assert(kN <= kNccMaxPixels, "patches within the NCC bound");
    static_assert(N1 < kNone && N2 < kNone, "indices fit uint16_t with a spare value");
    MatchStats st;
    const uint16_t n1 = prev.count <= N1 ? prev.count : N1;
    const uint16_t n2 = cur.count <= N2 ? cur.count : N2;
    detail::PatchSums ps[N1], cs[N2];
    uint16_t best_cur[N1], best_prev[N2];
    int32_t best_score[N1], second_score[N1], best_score_cur[N2];  // kNoScore: none yet
    for (uint16_t j = 0; j < n2; ++j) {
        cs[j] = detail::patch_sums(cur.items[j], config.min_variance);
        best_prev[j] = kNone;
        best_score_cur[j] = kNoScore;
    }
    const int32_t radius = config.search_radius_px;
    for (uint16_t i = 0; i < n1; ++i) {
        ps[i] = detail::patch_sums(prev.items[i], config.min_variance);
        best_cur[i] = kNone;
        best_score[i] = second_score[i] = kNoScore;
        if (ps[i].flat) continue;
        const int32_t ex = prev.items[i].px + config.offset_x,
                      ey = prev.items[i].py + config.offset_y;
        for (uint16_t j = 0; j < n2; ++j) {
            const int32_t dx = cur.items[j].px - ex, dy = cur.items[j].py - ey;
            if (cs[j].flat || dx < -radius || dx > radius || dy < -radius || dy > radius) continue;
            NccSums s;
            s.n = kN;
            s.sa = ps[i].sum;
            s.saa = ps[i].sum_sq;
            s.sb = cs[j].sum;
            s.sbb = cs[j].sum_sq;
            s.sab = detail::patch_dot(prev.items[i], cur.items[j]);
            const int16_t q = ncc_from_sums(s, config.min_variance).q15;
            ++st.scored;
            if (q > best_score[i]) {
                second_score[i] = best_score[i];
                best_score[i] = q;
                best_cur[i] = j;
            } else if (q > second_score[i]) {
                second_score[i] = q;
            }
            if (q > best_score_cur[j]) {
                best_score_cur[j] = q;
                best_prev[j] = i;
            }
        }
    }
    uint16_t written = 0;
    for (uint16_t i = 0; i < n1; ++i) {
        const uint16_t j = best_cur[i];
        if (ps[i].flat) {
            ++st.flat;
        } else if (j == kNone) {
            ++st.no_candidate;
        } else if (best_score[i] < config.min_score_q15) {
            ++st.below_min;
        } else if (second_score[i] != kNoScore &&
                   best_score[i] - second_score[i] < config.min_margin_q15) {
            ++st.ambiguous;
        } else if (config.mutual && best_prev[j] != i) {
            ++st.not_mutual;
        } else if (written == capacity) {
            ++st.dropped_capacity;
        } else {
            out[written++] = FeatureMatch{i, j, static_cast<int16_t>(best_score[i])};
        }
    }
    if (stats) *stats = st;
    return written;
}

}  // namespace qt

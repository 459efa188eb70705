#include "lines/edge_stage.h"

#include <string.h>

#include "base/fixed.h"

#if defined(__ARM_FEATURE_SIMD32)
#include <arm_acle.h>
#endif

// Targets whose compiler vectorises plain loops (x86-64's SSE2, aarch64's NEON) test blocks of
// 32 entries for an edge in one vectorised pass; 32-bit microcontrollers, where that pass
// costs more than it saves, test one entry (or four, with a 64-bit add) at a time. Both give
// the same rows: the chain test compares the Cortex-M output with the host's byte for byte.
#if defined(__SSE2__) || defined(__ARM_NEON)
#define QT_VECTOR_UNIT 1
#else
#define QT_VECTOR_UNIT 0
#endif

namespace qt {

namespace {

// The group tests below: bit 9 (kReached) of m + threshold_bias(t) is set exactly when a 9-bit
// magnitude m reaches the threshold t, and no sum carries past bit 9 (0x1FF + 0x1FF < 0x400),
// for t in 1..510; outside that range the bit may be set needlessly, never missed.
constexpr uint32_t kReached = 0x200;
constexpr uint16_t threshold_bias(uint16_t t) { return static_cast<uint16_t>(kReached - t); }
#if QT_VECTOR_UNIT
constexpr int32_t kBlock = 32;  // entries per group test in the vectorised loops
#endif

}  // namespace

void pack_nms_row(const gradient_word* words, uint16_t width, uint16_t* row) {
    row[0] = 0;
    for (uint16_t x = 0; x < width; ++x)
        row[x + 1] = nms_entry(gradient_mag(words[x]), gradient_dir(words[x]));
    row[width + 1] = 0;
}

void gradient_nms_row(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                      uint16_t width, uint16_t edge_threshold, uint16_t* row) {
    row[0] = 0;
    row[width + 1] = 0;
    gradient_nms_span(above, center, below, width, 0, width, edge_threshold, row);
}

void gradient_nms_span(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                       uint16_t width, uint16_t x_begin, uint16_t x_end, uint16_t edge_threshold,
                       uint16_t* row) {
    auto magnitude = [](int32_t gx, int32_t gy) {
        return static_cast<uint16_t>((gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy));
    };
    // The direction only where NMS will read it, where the magnitude reaches the threshold.
    auto pack = [&](int32_t gx, int32_t gy) {
        const uint16_t mag = magnitude(gx, gy);
        return mag >= edge_threshold ? nms_entry(mag, direction_bin(gx, gy)) : mag;
    };
    auto gy_at = [above, below](int32_t x) { return static_cast<int32_t>(below[x]) - above[x]; };
    auto inner = [&](int32_t x) {  // 0 < x < width - 1: no border tests
        return pack(static_cast<int32_t>(center[x + 1]) - center[x - 1], gy_at(x));
    };
    const int32_t last = width - 1;  // borders replicated
    if (x_begin >= x_end) return;
    if (width == 1) {
        row[1] = pack(0, gy_at(0));
        return;
    }
    if (x_begin == 0) row[1] = pack(static_cast<int32_t>(center[1]) - center[0], gy_at(0));
    if (x_end == width)
        row[last + 1] = pack(static_cast<int32_t>(center[last]) - center[last - 1], gy_at(last));
    // The columns between the borders, [x, stop).
    const int32_t stop = x_end < width ? x_end : last;
#if defined(__ARM_FEATURE_SIMD32)
    // Cortex-M4/M7 (DSP extension): four pixels per step in byte and half-word lanes, exact
    // magnitudes; a group with a pixel at or above the threshold goes through pack(). About a
    // quarter of the plain loop's instructions per pixel.
    int32_t x = x_begin > 0 ? x_begin : 1;
    if (edge_threshold >= 1) {
        const uint16x2_t below_threshold = (edge_threshold - 1u) * 0x00010001u;
        auto load4 = [](const uint8_t* p) {
            uint8x4_t v;
            memcpy(&v, p, sizeof v);  // an unaligned LDR: allowed on ARMv7-M
            return v;
        };
        for (; x + 4 <= stop; x += 4) {
            const uint8x4_t left = load4(center + x - 1), right = load4(center + x + 1);
            const uint8x4_t up = load4(above + x), down = load4(below + x);
            const uint8x4_t agx = __uqsub8(right, left) | __uqsub8(left, right);  // |gx|, 4 lanes
            const uint8x4_t agy = __uqsub8(down, up) | __uqsub8(up, down);        // |gy|
            const uint16x2_t even = __uadd16(__uxtb16(agx), __uxtb16(agy));       // pixels x, x + 2
            const uint16x2_t odd =
                __uadd16(__uxtb16(agx >> 8), __uxtb16(agy >> 8));  // x + 1, x + 3
            if ((__uqsub16(even, below_threshold) | __uqsub16(odd, below_threshold)) == 0) {
                const uint32_t first = (even & 0xFFFFu) | (odd << 16),
                               second = (even >> 16) | (odd & 0xFFFF0000u);
                memcpy(row + x + 1, &first, sizeof first);
                memcpy(row + x + 3, &second, sizeof second);
                continue;
            }
            for (int32_t k = x; k < x + 4; ++k) row[k + 1] = inner(k);
        }
    }
    for (; x < stop; ++x) row[x + 1] = inner(x);
#elif QT_VECTOR_UNIT
    // Blocks of 32 pixels: the magnitudes, branch-free so that the host compiler vectorises
    // the loop (pack()'s branch stops it), noting whether any reaches the threshold; then,
    // only in a block where one does, the directions. Few blocks hold an edge.
    const uint16_t bias = threshold_bias(edge_threshold);
    int32_t x = x_begin > 0 ? x_begin : 1;
    for (; x + kBlock <= stop; x += kBlock) {
        uint16_t reached = 0;
        for (int32_t k = x; k < x + kBlock; ++k) {
            const uint16_t m =
                magnitude(static_cast<int32_t>(center[k + 1]) - center[k - 1], gy_at(k));
            row[k + 1] = m;
            reached |= static_cast<uint16_t>(m + bias);
        }
        if ((reached & kReached) == 0) continue;
        for (int32_t k = x; k < x + kBlock; ++k)
            if (row[k + 1] >= edge_threshold) row[k + 1] = inner(k);
    }
    for (; x < stop; ++x) row[x + 1] = inner(x);
#else
    for (int32_t x = x_begin > 0 ? x_begin : 1; x < stop; ++x) row[x + 1] = inner(x);
#endif
}

namespace {

// The NMS decision for padded index i (pixel i - 1) and its sub-pixel peak.
inline void nms_pixel(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint32_t i,
                      uint16_t edge_threshold, EdgeList& out) {
    const uint32_t m = c[i] & 0x1FFu;
    if (m < edge_threshold) return;
    const uint32_t dir = (c[i] >> 9) & 15u;
    auto M = [](const uint16_t* r, uint32_t k) { return static_cast<uint32_t>(r[k] & 0x1FFu); };
    uint32_t ahead, behind, mm = 2 * m;  // odd axes compare 2m with a sum of two
    switch (dir & 7u) {  // ahead = along +gradient (y down), behind = along -gradient
        case 0:
            ahead = M(c, i + 1);
            behind = M(c, i - 1);
            mm = m;
            break;
        case 2:
            ahead = M(b, i + 1);
            behind = M(a, i - 1);
            mm = m;
            break;
        case 4:
            ahead = M(b, i);
            behind = M(a, i);
            mm = m;
            break;
        case 6:
            ahead = M(b, i - 1);
            behind = M(a, i + 1);
            mm = m;
            break;
        case 1:
            ahead = M(c, i + 1) + M(b, i + 1);
            behind = M(c, i - 1) + M(a, i - 1);
            break;
        case 3:
            ahead = M(b, i + 1) + M(b, i);
            behind = M(a, i - 1) + M(a, i);
            break;
        case 5:
            ahead = M(b, i) + M(b, i - 1);
            behind = M(a, i) + M(a, i + 1);
            break;
        default:
            ahead = M(b, i - 1) + M(c, i - 1);
            behind = M(a, i + 1) + M(c, i + 1);
            break;
    }
    // Bins 8..15 point the other way along the same axis: swap the roles so that the tie
    // rule follows the gradient, not the axis.
    if (dir >= 8) {
        const uint32_t t = ahead;
        ahead = behind;
        behind = t;
    }
    if (!(mm > ahead && mm >= behind)) return;
    // Parabola through (behind, mm, ahead) at -1, 0, +1: peak at
    // (behind - ahead) / (2·(behind - 2mm + ahead)) steps, in [-1/2, 1/2) by the tests above;
    // in 1/16 step: 8·(behind - ahead) / (behind + ahead - 2mm), rounded half away.
    const int32_t num = 8 * (static_cast<int32_t>(behind) - static_cast<int32_t>(ahead));
    const int32_t den = static_cast<int32_t>(behind + ahead) - 2 * static_cast<int32_t>(mm);
    int32_t delta16 = static_cast<int32_t>(div_round_half_away(num, den));
    delta16 = delta16 < -8 ? -8 : delta16 > 7 ? 7 : delta16;
    out.push(static_cast<uint16_t>(i - 1), dir, delta16, m);
}

}  // namespace

void nms_row(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t width, uint16_t y,
             uint16_t edge_threshold, EdgeList& out) {
    out.begin_row(y);
    nms_span(a, c, b, 0, width, edge_threshold, out);
}

void nms_span(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t x_begin,
              uint16_t x_end, uint16_t edge_threshold, EdgeList& out) {
    // Most pixels are below the threshold: skip them a group at a time (threshold_bias).
    uint32_t i = x_begin + 1u;         // index x + 1 in the padded rows
    const uint32_t stop = x_end + 1u;  // ... up to this one, excluded
#if QT_VECTOR_UNIT
    const uint16_t bias = threshold_bias(edge_threshold);
    for (; i + kBlock <= stop; i += kBlock) {
        uint16_t reached = 0;
        for (uint32_t k = i; k < i + kBlock; ++k)
            reached |= static_cast<uint16_t>((c[k] & 0x1FFu) + bias);
        if ((reached & kReached) == 0) continue;
        for (uint32_t k = i; k < i + kBlock; ++k) nms_pixel(a, c, b, k, edge_threshold, out);
    }
#else
    // Four 16-bit lanes in one 64-bit add.
    const uint64_t lanes = 0x0001000100010001ULL;
    const uint64_t bias = threshold_bias(edge_threshold) * lanes;
    while (i + 4 <= stop) {
        uint64_t four;
        memcpy(&four, c + i, sizeof four);
        if ((((four & (0x1FFu * lanes)) + bias) & (kReached * lanes)) == 0) {
            i += 4;
            continue;
        }
        const uint32_t end = i + 4;
        for (; i < end; ++i) nms_pixel(a, c, b, i, edge_threshold, out);
    }
#endif
    for (; i < stop; ++i) nms_pixel(a, c, b, i, edge_threshold, out);
}

}  // namespace qt

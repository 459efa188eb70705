#include "target/template_search.h"

namespace qt {

namespace {

// Offset of the parabola's vertex through (−1, a), (0, b), (1, c) with b the maximum, in
// 1/256 px: 128·(a − c) / (a − 2b + c), clamped to ±128 (half a pixel). Scores are Q15, so
// the numerator stays within ±2^24 and the denominator within ±2^18: int32 suffices.
int32_t vertex_q8(int32_t a, int32_t b, int32_t c) {
    const int32_t den = a - 2 * b + c;
    if (den >= 0) return 0;  // flat or not a maximum: no sub-pixel information
    int32_t v = 128 * (a - c) / den;
    return v < -128 ? -128 : v > 128 ? 128 : v;
}

}  // namespace

TemplateHit search_template(const uint8_t* tpl, uint8_t tw, uint8_t th, const PixelRegion& region,
                            int32_t cx, int32_t cy, uint16_t radius) {
    TemplateHit hit;
    if (tw == 0 || th == 0 || uint32_t{tw} * th > kNccMaxPixels || region.w < tw || region.h < th)
        return hit;
    // Top-left corners whose centre (u + (tw − 1)/2, v + (th − 1)/2) is within ±radius of
    // (cx, cy), and whose template lies in the region.
    const int32_t uc = cx - (tw - 1) / 2, vc = cy - (th - 1) / 2;
    int32_t u0 = uc - radius, u1 = uc + radius, v0 = vc - radius, v1 = vc + radius;
    if (u0 < region.x0) u0 = region.x0;
    if (v0 < region.y0) v0 = region.y0;
    if (u1 > region.x0 + region.w - tw) u1 = region.x0 + region.w - tw;
    if (v1 > region.y0 + region.h - th) v1 = region.y0 + region.h - th;
    // The template's Σa and Σa² are the same at every candidate: summed once here, so each
    // candidate costs only Σb, Σb² and Σab (3 multiply-adds a pixel instead of 5).
    NccSums t;
    t.n = uint32_t{tw} * th;
    for (uint32_t i = 0; i < t.n; ++i) {
        t.sa += tpl[i];
        t.saa += uint32_t{tpl[i]} * tpl[i];
    }
    auto score = [&](int32_t u, int32_t v) {
        const uint8_t* at = region.pixels + static_cast<uint32_t>(v - region.y0) * region.stride +
                            static_cast<uint32_t>(u - region.x0);
        NccSums s = t;
        for (uint8_t y = 0; y < th; ++y)
            ncc_add_row<false>(tpl + uint32_t{y} * tw, at + uint32_t{y} * region.stride, tw, s);
        return static_cast<int32_t>(ncc_from_sums(s).q15);
    };
    int32_t best = INT32_MIN, bu = 0, bv = 0;
    for (int32_t v = v0; v <= v1; ++v)
        for (int32_t u = u0; u <= u1; ++u) {
            const int32_t s = score(u, v);
            ++hit.positions;
            if (s > best) {
                best = s;
                bu = u;
                bv = v;
            }
        }
    if (hit.positions == 0) return hit;
    hit.found = true;
    hit.score_q15 = static_cast<int16_t>(best);
    const int32_t dx =
        bu > u0 && bu < u1 ? vertex_q8(score(bu - 1, bv), best, score(bu + 1, bv)) : 0;
    const int32_t dy =
        bv > v0 && bv < v1 ? vertex_q8(score(bu, bv - 1), best, score(bu, bv + 1)) : 0;
    hit.x_q8 = bu * 256 + (tw - 1) * 128 + dx;
    hit.y_q8 = bv * 256 + (th - 1) * 128 + dy;
    return hit;
}

}  // namespace qt

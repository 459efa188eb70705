#include "quads/display_homography.h"

namespace qt {

bool display_homography(const Point16 corners[4], uint16_t display_width, uint16_t display_height,
                        DisplayHomography& out) {
    if (display_width == 0 || display_height == 0) return false;
    // Unit-square corners (0,0), (1,0), (1,1), (0,1) go to P0..P3 = TL, TR, BR, BL.
    const Point16* p[4] = {&corners[0], &corners[3], &corners[2], &corners[1]};
    int64_t x[4], y[4];  // 1/256 px (q24_8), |x| <= 2^19 for |corner| <= 2048 px
    const int64_t limit = int64_t{2048} * q16_16::one_raw;
    for (int i = 0; i < 4; ++i) {
        if (abs64(p[i]->x.raw) > limit || abs64(p[i]->y.raw) > limit) return false;
        x[i] = shr_round_half_away(p[i]->x.raw, 8);
        y[i] = shr_round_half_away(p[i]->y.raw, 8);
    }
    // Heckbert's solution; every difference below 2^21 (1/256 px), products below 2^43.
    const int64_t sx = x[0] - x[1] + x[2] - x[3], sy = y[0] - y[1] + y[2] - y[3];
    const int64_t dx1 = x[1] - x[2], dx2 = x[3] - x[2], dy1 = y[1] - y[2], dy2 = y[3] - y[2];
    int64_t den = dx1 * dy2 - dx2 * dy1;  // 2^-16 px²
    int64_t gn = sx * dy2 - dx2 * sy, hn = dx1 * sy - sx * dy1;
    if (den == 0) return false;
    // g = gn / den and h = hn / den in q2_30 (unit square): scale all three down together
    // until each is below 2^31 so that gn·2^30 fits in 64 bits; den keeps >= 2^22 significant
    // bits unless the quadrangle is tiny, which the rules exclude.
    while (abs64(den) >= (int64_t{1} << 31) || abs64(gn) >= (int64_t{1} << 31) ||
           abs64(hn) >= (int64_t{1} << 31)) {
        den = shr_round_half_away(den, 1);
        gn = shr_round_half_away(gn, 1);
        hn = shr_round_half_away(hn, 1);
    }
    if (den == 0) return false;
    const int64_t g_sq = div_round_half_away(gn * pow2(30), den);  // q2_30 per unit square
    const int64_t h_sq = div_round_half_away(hn * pow2(30), den);
    // |g|, |h| <= 2^10 keeps the products below 2^60; beyond that the quadrangle has a corner
    // near its horizon and is no board.
    if (abs64(g_sq) > (int64_t{1} << 40) || abs64(h_sq) > (int64_t{1} << 40)) return false;

    // a = (x1 − x0 + g·x1) / W in q12_20: numerator in 2^-38 px (q8 · q30), then / (W·2^18).
    const int64_t W = display_width, H = display_height;
    const int64_t a = div_round_half_away((x[1] - x[0]) * pow2(30) + g_sq * x[1], W * pow2(18));
    const int64_t d = div_round_half_away((y[1] - y[0]) * pow2(30) + g_sq * y[1], W * pow2(18));
    const int64_t b = div_round_half_away((x[3] - x[0]) * pow2(30) + h_sq * x[3], H * pow2(18));
    const int64_t e = div_round_half_away((y[3] - y[0]) * pow2(30) + h_sq * y[3], H * pow2(18));
    const int64_t g = div_round_half_away(g_sq, W), h = div_round_half_away(h_sq, H);
    const int64_t max32 = int_limits<int32_t>::hi;
    if (abs64(a) > max32 || abs64(b) > max32 || abs64(d) > max32 || abs64(e) > max32 ||
        abs64(g) > max32 || abs64(h) > max32)
        return false;
    out.a = q12_20::from_raw(a);
    out.b = q12_20::from_raw(b);
    out.d = q12_20::from_raw(d);
    out.e = q12_20::from_raw(e);
    out.c = q16_16::from_raw(x[0] * 256);
    out.f = q16_16::from_raw(y[0] * 256);
    out.g = q2_30::from_raw(g);
    out.h = q2_30::from_raw(h);
    return true;
}

bool map_display_point(const DisplayHomography& m, q16_16 u, q16_16 v, Point16& out) {
    // w in q18_46: g (q2_30) · u (q16_16); with |u|, |v| <= 4096 px (2^28 raw) every term
    // stays below 2^59.
    const int64_t max_uv = int64_t{4096} * q16_16::one_raw;
    if (abs64(u.raw) > max_uv || abs64(v.raw) > max_uv) return false;
    const int64_t w46 =
        static_cast<int64_t>(m.g.raw) * u.raw + static_cast<int64_t>(m.h.raw) * v.raw + pow2(46);
    const int64_t w30 = shr_round_half_away(w46, 16);
    if (w30 <= (int64_t{1} << 10)) return false;  // w <= 2^-20
    // x·w in q28_36: a (q12_20) · u (q16_16) + c (q16_16) · 2^20; |x·w| < 2^47 for sane
    // inputs, so the · 2^10 below stays under 2^57.
    const int64_t xw = static_cast<int64_t>(m.a.raw) * u.raw +
                       static_cast<int64_t>(m.b.raw) * v.raw +
                       static_cast<int64_t>(m.c.raw) * pow2(20);
    const int64_t yw = static_cast<int64_t>(m.d.raw) * u.raw +
                       static_cast<int64_t>(m.e.raw) * v.raw +
                       static_cast<int64_t>(m.f.raw) * pow2(20);
    if (abs64(xw) >= pow2(52) || abs64(yw) >= pow2(52)) return false;
    out.x = q16_16::from_raw(div_round_half_away(xw * pow2(10), w30));  // 2^-36 · 2^10 / 2^-30
    out.y = q16_16::from_raw(div_round_half_away(yw * pow2(10), w30));
    return true;
}

}  // namespace qt

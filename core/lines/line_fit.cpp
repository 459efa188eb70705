#include "lines/line_fit.h"

namespace qt {

bool fit_line(const Moments& m, int32_t anchor_x32, int32_t anchor_y32, FittedLine& out) {
    if (m.n <= 0) return false;
    // Central second moments (×1, in (1/32 px)²); the divisions round towards zero, an error
    // of under one unit against sums of thousands.
    int64_t cxx = m.sxx - div_by_small(m.sx * m.sx, m.n);
    int64_t cyy = m.syy - div_by_small(m.sy * m.sy, m.n);
    int64_t cxy = m.sxy - div_by_small(m.sx * m.sy, m.n);
    int64_t a = 2 * cxy, b = cxx - cyy;
    // Halved (truncating towards zero) until both are below 2^30: k halvings at once, k from
    // the larger magnitude's top bit.
    const uint64_t larger = static_cast<uint64_t>(abs64(a) > abs64(b) ? abs64(a) : abs64(b));
    if (larger >= (uint64_t{1} << 30)) {
        const int k = 64 - __builtin_clzll(larger) - 30;
        a = shr_toward_zero(a, k);
        b = shr_toward_zero(b, k);
    }
    // Direction angle φ in [0°, 180°): half of the angle of (Sxx − Syy, 2 Sxy).
    const angle_t phi = atan2_angle(static_cast<int32_t>(a), static_cast<int32_t>(b)) / 2;
    const SinCos sc = sin_cos(phi);
    q2_30 dx = sc.cos, dy = sc.sin;
    if (dx.raw < 0 || (dx.raw == 0 && dy.raw < 0)) {
        dx = neg_sat(dx);
        dy = neg_sat(dy);
    }
    out.dx = dx;
    out.dy = dy;
    // Centroid: anchor + mean, 1/32 px -> q16_16 is ×2^11.
    out.mx = q16_16::from_raw(static_cast<int64_t>(anchor_x32) * 2048 +
                              div_round_half_away(m.sx * 2048, m.n));
    out.my = q16_16::from_raw(static_cast<int64_t>(anchor_y32) * 2048 +
                              div_round_half_away(m.sy * 2048, m.n));
    return true;
}

q16_16 along(const FittedLine& line, q16_16 px, q16_16 py) {
    const int64_t ex = static_cast<int64_t>(px.raw) - line.mx.raw;
    const int64_t ey = static_cast<int64_t>(py.raw) - line.my.raw;
    return q16_16::from_raw(shr_round_half_away(ex * line.dx.raw + ey * line.dy.raw, 30));
}

Segment make_segment(const FittedLine& line, q16_16 t1, q16_16 t2, uint16_t points) {
    Segment s{};
    auto point_at = [&](q16_16 t, q16_16& x, q16_16& y) {
        x = q16_16::from_raw(line.mx.raw +
                             shr_round_half_away(static_cast<int64_t>(t.raw) * line.dx.raw, 30));
        y = q16_16::from_raw(line.my.raw +
                             shr_round_half_away(static_cast<int64_t>(t.raw) * line.dy.raw, 30));
    };
    point_at(t1, s.x1, s.y1);
    point_at(t2, s.x2, s.y2);
    // Unit normal (−dy, dx); rho = centroid · normal, made non-negative by turning the normal.
    int64_t nx = -static_cast<int64_t>(line.dy.raw), ny = line.dx.raw;
    int64_t rho = shr_round_half_away(line.mx.raw * nx + line.my.raw * ny, 30);
    if (rho < 0) {
        rho = -rho;
        nx = -nx;
        ny = -ny;
    }
    s.rho = q16_16::from_raw(rho);
    s.theta = atan2_angle(static_cast<int32_t>(ny), static_cast<int32_t>(nx));
    s.cx = q16_16::from_raw(shr_round_half_away(rho * nx, 30));
    s.cy = q16_16::from_raw(shr_round_half_away(rho * ny, 30));
    s.points = points;
    return s;
}

}  // namespace qt

#include "quads/quad_rules.h"

#include "base/isqrt.h"
#include "lines/line_cluster.h"

namespace qt {

namespace {

int64_t wide(q16_16 v) { return v.raw; }

}  // namespace

QuadParams sized_quad_params(const QuadParams& p, uint16_t height) {
    QuadParams sized = p;
    if (sized.min_side_length.raw == 0)
        sized.min_side_length = q16_16::from_int(height >= 20 ? height / 10 : 1);
    return sized;
}

angle_t line_orientation(const Segment& s) { return s.theta & (kAngleHalfTurn - 1u); }

bool rule_parallel(angle_t theta_a, angle_t theta_b, const QuadParams& p) {
    return orientation_difference(theta_a, theta_b) <= p.parallel_tolerance;
}

bool rule_perpendicular(angle_t theta_a, angle_t theta_b, const QuadParams& p) {
    return kAngleQuarterTurn - orientation_difference(theta_a, theta_b) <=
           p.perpendicular_tolerance;
}

bool rule_corners_inside(const Point16 corners[4], uint16_t width, uint16_t height,
                         const QuadParams& p) {
    // Outer pixel edges at -0.5 and size - 0.5; compare in q16_16 raw units, 64-bit.
    const int64_t half = q16_16::one_raw / 2;
    const int64_t lo = -half + wide(p.corner_margin);
    const int64_t hi_x =
        static_cast<int64_t>(width) * q16_16::one_raw - half - wide(p.corner_margin);
    const int64_t hi_y =
        static_cast<int64_t>(height) * q16_16::one_raw - half - wide(p.corner_margin);
    for (int i = 0; i < 4; ++i) {
        const int64_t x = wide(corners[i].x), y = wide(corners[i].y);
        if (x < lo || x > hi_x || y < lo || y > hi_y) return false;
    }
    return true;
}

bool rule_side_lengths(const q16_16 sides[4], const QuadParams& p) {
    for (int i = 0; i < 4; ++i)
        if (sides[i] < p.min_side_length || sides[i] > p.max_side_length) return false;
    return true;
}

angle_t opposite_convergence(const Segment* const lines[4]) {
    const angle_t a = orientation_difference(lines[0]->theta, lines[2]->theta);
    const angle_t b = orientation_difference(lines[1]->theta, lines[3]->theta);
    return a > b ? a : b;
}

bool rule_aspect(const q16_16 sides[4], angle_t convergence, const QuadParams& p) {
    // ratio = w / h with w = s1 + s3, h = s0 + s2 (the halves cancel). Accept when
    // aspect / tol <= w / h <= aspect · tol, i.e. w·tol >= aspect·h and w <= aspect·tol·h.
    // Sides <= 2^15 px (2^31 raw) and aspect, tol <= 2^15: products stay below 2^63 after the
    // q16_16 multiplication shifts.
    const int64_t w = wide(sides[1]) + wide(sides[3]);
    const int64_t h = wide(sides[0]) + wide(sides[2]);
    const bool tilted =
        convergence >= p.perspective_convergence && p.tilted_aspect_tolerance > p.aspect_tolerance;
    const int64_t aspect = wide(p.display_aspect),
                  tol = wide(tilted ? p.tilted_aspect_tolerance : p.aspect_tolerance);
    const int64_t aspect_h = (aspect * h) >> 16;  // q16_16
    const int64_t w_tol = (w * tol) >> 16;        // q16_16
    const int64_t aspect_tol_h = (((aspect * tol) >> 16) * h) >> 16;
    return w_tol >= aspect_h && w <= aspect_tol_h;
}

bool rule_contrast(const Point16 corners[4], const Segment* const sides[4], const SinCos normals[4],
                   const QuadParams& p) {
    if (p.contrast == Contrast::any) return true;
    int64_t mx = 0, my = 0;  // the centroid, q16_16; |corner| <= 16384 px keeps it below 2^30
    for (int i = 0; i < 4; ++i) {
        mx += corners[i].x.raw;
        my += corners[i].y.raw;
    }
    mx /= 4;
    my /= 4;
    for (int i = 0; i < 4; ++i) {
        const Segment& s = *sides[i];
        if (s.bright_side == 0) continue;
        // The centroid of a convex quadrangle with sides >= 1 px is never on a side's line.
        const bool interior_along_normal = signed_distance(s, normals[i], mx, my) > 0;
        const bool interior_bright = interior_along_normal == (s.bright_side > 0);
        if (interior_bright != (p.contrast == Contrast::bright_board)) return false;
    }
    return true;
}

bool intersect_lines(const Segment& a, const Segment& b, Point16& out) {
    return intersect_lines(a, sin_cos(a.theta), b, sin_cos(b.theta), out);
}

bool intersect_lines(const Segment& a, SinCos na, const Segment& b, SinCos nb, Point16& out) {
    // Normals n = (cos θ, sin θ) in q2_30; the lines are n·p = rho. Cramer's rule:
    //   det = ca·sb − sa·cb (q4_60 -> q2_30), x = (ra·sb − rb·sa) / det, y = (ca·rb − cb·ra) / det.
    // |rho| < 2^15 px (2^31 raw) times |sin| <= 2^30: each product below 2^61, the difference
    // below 2^62.
    const int64_t det = shr_round_half_away(static_cast<int64_t>(na.cos.raw) * nb.sin.raw -
                                                static_cast<int64_t>(na.sin.raw) * nb.cos.raw,
                                            30);                              // q2_30
    if (det > -(int64_t{1} << 20) && det < (int64_t{1} << 20)) return false;  // |sin| < 2^-10
    const int64_t nx = wide(a.rho) * nb.sin.raw - wide(b.rho) * na.sin.raw;   // q16_46
    const int64_t ny =
        static_cast<int64_t>(na.cos.raw) * b.rho.raw - static_cast<int64_t>(nb.cos.raw) * a.rho.raw;
    const int64_t x = div_round_half_away(nx, det), y = div_round_half_away(ny, det);  // q16_16
    const int64_t limit = int64_t{16384} * q16_16::one_raw;
    if (x < -limit || x > limit || y < -limit || y > limit) return false;
    out = {q16_16::from_raw(x), q16_16::from_raw(y)};
    return true;
}

uint64_t distance2(Point16 a, Point16 b) {
    const int64_t dx = wide(b.x) - wide(a.x), dy = wide(b.y) - wide(a.y);  // |d| < 2^32
    // dx² + dy² < 2^63 for coordinates within ±2^30 raw (±16384 px), as intersect_lines gives.
    return static_cast<uint64_t>(dx * dx + dy * dy);
}

q16_16 distance(Point16 a, Point16 b) { return q16_16::from_raw(isqrt64(distance2(a, b))); }

int64_t shoelace2(const Point16 c[4]) {
    int64_t sum = 0;
    for (int i = 0; i < 4; ++i) {
        const Point16 p = c[i], q = c[(i + 1) & 3];
        sum += wide(p.x) * wide(q.y) - wide(q.x) * wide(p.y);  // each term < 2^61
    }
    return sum;
}

bool is_convex(const Point16 c[4]) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const Point16 a = c[i], b = c[(i + 1) & 3], d = c[(i + 2) & 3];
        const int64_t cross = (wide(b.x) - wide(a.x)) * (wide(d.y) - wide(b.y)) -
                              (wide(b.y) - wide(a.y)) * (wide(d.x) - wide(b.x));
        const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
        if (s == 0 || (sign != 0 && s != sign)) return false;
        sign = s;
    }
    return true;
}

q16_16 side_overlap(Point16 a, Point16 b, const Segment& s) {
    const int64_t ux = wide(b.x) - wide(a.x), uy = wide(b.y) - wide(a.y);
    const int64_t len = isqrt64(static_cast<uint64_t>(ux * ux + uy * uy));  // q16_16
    if (len == 0) return q16_16::from_raw(0);
    // Position along a -> b, q16_16: dot(p − a, u) / |u|. Coordinates within ±2^30 raw.
    auto t = [&](q16_16 x, q16_16 y) {
        return ((wide(x) - wide(a.x)) * ux + (wide(y) - wide(a.y)) * uy) / len;
    };
    int64_t t1 = t(s.x1, s.y1), t2 = t(s.x2, s.y2);
    if (t1 > t2) {
        const int64_t swap = t1;
        t1 = t2;
        t2 = swap;
    }
    const int64_t lo = t1 > 0 ? t1 : 0, hi = t2 < len ? t2 : len;
    return q16_16::from_raw(hi > lo ? hi - lo : 0);
}

}  // namespace qt

#include "tracking/line_tracker.h"

#include "base/wide_mul.h"

namespace qt {

namespace {

// n·p for a unit normal n (q2_30) and a point p (q16_16): pixels, q16_16 raw, rounded half away.
int64_t dot_normal(SinCos n, q16_16 x, q16_16 y) {
    return shr_round_half_away(
        static_cast<int64_t>(n.cos.raw) * x.raw + static_cast<int64_t>(n.sin.raw) * y.raw, 30);
}

// v·c for v in q16_16 raw (|v| <= 2^31) and c in q2_30: q16_16, rounded half away.
q16_16 scale(int64_t v, q2_30 c) { return q16_16::from_raw(shr_round_half_away(v * c.raw, 30)); }

// The closest point of line m to the origin o, relative to o: T_i of §2.7.
void closest_point(const Segment& m, SinCos n, Point16 o, q16_16& cx, q16_16& cy) {
    const int64_t rho = static_cast<int64_t>(m.rho.raw) - dot_normal(n, o.x, o.y);
    cx = scale(rho, n.cos);
    cy = scale(rho, n.sin);
}

// (|(x, y)|/2)² in q16_16 raw squared: halved so that the sum of squares of two int32 raw values
// (each up to 2^62) cannot overflow.
int64_t half_radius2(q16_16 x, q16_16 y) {
    const int64_t hx = x.raw / 2, hy = y.raw / 2;
    return hx * hx + hy * hy;
}

// Degrees in [-180, 180) for any q16_16 angle within ±540°.
q16_16 wrap_deg(int64_t deg_raw) {
    const int64_t turn = 360 * q16_16::one_raw, half = 180 * q16_16::one_raw;
    while (deg_raw >= half) deg_raw -= turn;
    while (deg_raw < -half) deg_raw += turn;
    return q16_16::from_raw(deg_raw);
}

}  // namespace

LineTrackerParams default_line_tracker_params(uint16_t width, uint16_t height) {
    LineTrackerParams p;
    const int64_t w1 = width > 0 ? width - 1 : 0, h1 = height > 0 ? height - 1 : 0;
    p.origins[0] = Point16{q16_16::from_int(0), q16_16::from_int(0)};
    p.origins[1] = Point16{q16_16::from_int(w1), q16_16::from_int(0)};
    p.origins[2] = Point16{q16_16::from_ratio(w1, 2), q16_16::from_int(h1)};
    p.turn.anchor = Point16{q16_16::from_ratio(w1, 2), q16_16::from_ratio(h1, 2)};
    return p;
}

bool LineTracker::init(const Segment& measured, const LineTrackerParams& params) {
    params_ = params;
    bool ok = true;
    if (params_.filters < 1 || params_.filters > 3) {
        params_.filters = params_.filters < 1 ? 1 : 3;
        ok = false;
    }
    const SinCos n = sin_cos(measured.theta);
    if (params_.model == LineModel::closest_points) {
        for (int i = 0; i < params_.filters; ++i) {
            q16_16 cx, cy;
            closest_point(measured, n, params_.origins[i], cx, cy);
            ok = point_[i].init(cx, cy, params_.kalman) && ok;
        }
    } else {
        const TurnParams& t = params_.turn;
        angle_ = kalman_axis_init(angle_to_deg(measured.theta), t.r_angle, t.p0_turn);
        const int64_t rho =
            static_cast<int64_t>(measured.rho.raw) - dot_normal(n, t.anchor.x, t.anchor.y);
        offset_.init(q16_16::from_raw(rho), t.r_offset, t.p0_rate, t.p0_accel);
    }
    flags_ = 0;
    ends_[0] = Point16{measured.x1, measured.y1};
    ends_[1] = Point16{measured.x2, measured.y2};
    last_theta_ = measured.theta;
    last_bright_ = measured.bright_side;
    return ok;
}

void LineTracker::predict() {
    if (params_.model == LineModel::closest_points) {
        for (int i = 0; i < params_.filters; ++i) point_[i].predict();
        return;
    }
    offset_.predict(angle_.vel, params_.turn.q_offset);
    flags_ = static_cast<uint8_t>(flags_ | kalman_axis_predict(angle_, params_.turn.q_angle));
    angle_.pos = wrap_deg(angle_.pos.raw);  // a whole turn leaves n, and so ρ, unchanged
}

void LineTracker::update(const Segment& measured) {
    const SinCos n = sin_cos(measured.theta);
    if (params_.model == LineModel::closest_points) {
        for (int i = 0; i < params_.filters; ++i) {
            q16_16 cx, cy;
            closest_point(measured, n, params_.origins[i], cx, cy);
            point_[i].update(cx, cy);
        }
    } else {
        // The measured normal, or its opposite with rho negated, whichever lies within 90° of
        // the tracked θ: the same line, and a continuous (θ, ρ).
        const int64_t half = 180 * q16_16::one_raw, quarter = 90 * q16_16::one_raw;
        int64_t d =
            wrap_deg(static_cast<int64_t>(angle_to_deg(measured.theta).raw) - angle_.pos.raw).raw;
        int64_t sign = 1;
        if (d >= quarter) {
            d -= half;
            sign = -1;
        } else if (d < -quarter) {
            d += half;
            sign = -1;
        }
        const TurnParams& t = params_.turn;
        const int64_t rho =
            sign * (static_cast<int64_t>(measured.rho.raw) - dot_normal(n, t.anchor.x, t.anchor.y));
        flags_ = static_cast<uint8_t>(
            flags_ | kalman_axis_update(angle_, q16_16::from_raw(angle_.pos.raw + d), t.r_angle));
        offset_.update(q16_16::from_raw(rho), t.r_offset);
    }
    ends_[0] = Point16{measured.x1, measured.y1};
    ends_[1] = Point16{measured.x2, measured.y2};
    last_theta_ = measured.theta;
    last_bright_ = measured.bright_side;
}

uint8_t LineTracker::flags() const {
    bool sat = flags_ != 0;
    if (params_.model == LineModel::closest_points) {
        for (int i = 0; i < params_.filters; ++i) sat = sat || point_[i].saturated();
    } else {
        sat = sat || offset_.flags() != 0;
    }
    return sat ? LineTrackerFlags::saturated : 0;
}

int64_t LineTracker::innovation_variance(Point16 p) const {
    constexpr int64_t kMax = pow2(58);
    int64_t v = 0;
    if (params_.model == LineModel::closest_points) {
        for (int i = 0; i < params_.filters; ++i) {
            v = point_[i].axis_x().pp > v ? point_[i].axis_x().pp : v;
            v = point_[i].axis_y().pp > v ? point_[i].axis_y().pp : v;
        }
        v = clamp64(v, 0, kMax) + (static_cast<int64_t>(params_.kalman.r.raw) << 16);
    } else {
        // (π/180)² with 40 fraction bits: round(3.0461742e-4 · 2^40), for deg² -> rad².
        constexpr int64_t kRad2PerDeg2 = 334930395;
        const SinCos n = sin_cos(angle_from_deg(angle_.pos));
        const Point16 a = params_.turn.anchor;
        // t = (p − a)·(−sin θ, cos θ): px along the line from the anchor's foot, q16_16. Each
        // product is below 2^62 (|dx|, |dy| < 2^32, |sin|, |cos| <= 2^30 raw) and so is their
        // difference, at most |(dx, dy)|·2^30.
        const int64_t dx = static_cast<int64_t>(p.x.raw) - a.x.raw;
        const int64_t dy = static_cast<int64_t>(p.y.raw) - a.y.raw;
        const int64_t t =
            clamp64(shr_round_half_away(dy * n.cos.raw - dx * n.sin.raw, 30), -pow2(28), pow2(28));
        const int64_t lever2 = t * t;  // px², 32 fraction bits, <= 2^56
        const int64_t angle = mul_shr_round(angle_.pp, kRad2PerDeg2, 40);  // rad², 32 bits
        v = clamp64(offset_.cov()[0], 0, kMax) +
            clamp64(mul_shr_round(lever2, angle, 32), 0, kMax) +
            (static_cast<int64_t>(params_.turn.r_offset.raw) << 16);
    }
    return v < kMax ? v : kMax;
}

Segment LineTracker::finish(angle_t theta, int64_t rho_raw) const {
    if (rho_raw < 0) {
        rho_raw = -rho_raw;
        theta += kAngleHalfTurn;
    }
    const SinCos n = sin_cos(theta);
    Segment s{};
    s.rho = q16_16::from_raw(rho_raw);
    s.theta = theta;
    s.cx = scale(rho_raw, n.cos);
    s.cy = scale(rho_raw, n.sin);
    // End points: the last measured ones moved onto the line along its normal.
    q16_16* xs[2] = {&s.x1, &s.x2};
    q16_16* ys[2] = {&s.y1, &s.y2};
    for (int e = 0; e < 2; ++e) {
        const int64_t off = dot_normal(n, ends_[e].x, ends_[e].y) - rho_raw;
        *xs[e] = q16_16::from_raw(ends_[e].x.raw - scale(off, n.cos).raw);
        *ys[e] = q16_16::from_raw(ends_[e].y.raw - scale(off, n.sin).raw);
    }
    // Polarity is relative to the normal: it turns with it.
    const angle_t diff = theta - last_theta_;
    const bool opposite = diff > kAngleQuarterTurn && diff < kAngleQuarterTurn * 3u;
    s.bright_side = static_cast<int8_t>(opposite ? -last_bright_ : last_bright_);
    return s;
}

int LineTracker::farthest_filter() const {
    int far = 0;
    for (int i = 1; i < params_.filters; ++i)
        if (half_radius2(point_[i].x(), point_[i].y()) >
            half_radius2(point_[far].x(), point_[far].y()))
            far = i;
    return far;
}

Segment LineTracker::polar_line(int i) const {
    const q16_16 cx = point_[i].x(), cy = point_[i].y();
    const Point16 o = params_.origins[i];
    const int64_t rmin = params_.min_radius.raw / 2;  // halved like half_radius2()
    const angle_t theta =
        half_radius2(cx, cy) >= rmin * rmin ? atan2_angle(cy.raw, cx.raw) : last_theta_;
    const SinCos n = sin_cos(theta);
    const q16_16 px = q16_16::from_raw(static_cast<int64_t>(o.x.raw) + cx.raw);
    const q16_16 py = q16_16::from_raw(static_cast<int64_t>(o.y.raw) + cy.raw);
    return finish(theta, dot_normal(n, px, py));
}

Segment LineTracker::line() const {
    if (params_.model == LineModel::turn) {
        const angle_t theta = angle_from_deg(angle_.pos);
        const SinCos n = sin_cos(theta);
        const Point16 a = params_.turn.anchor;
        return finish(theta, static_cast<int64_t>(offset_.rho().raw) + dot_normal(n, a.x, a.y));
    }
    const int count = params_.filters;
    if (count == 1) return polar_line(0);
    // The points P_i = O_i + X_i (q16_16 raw) about their centroid.
    int64_t px[3] = {0, 0, 0}, py[3] = {0, 0, 0}, sx = 0, sy = 0;
    for (int i = 0; i < count; ++i) {
        px[i] = static_cast<int64_t>(params_.origins[i].x.raw) + point_[i].x().raw;
        py[i] = static_cast<int64_t>(params_.origins[i].y.raw) + point_[i].y().raw;
        sx += px[i];
        sy += py[i];
    }
    const int64_t mx = div_round_half_away(sx, count), my = div_round_half_away(sy, count);
    // Scale the offsets (|d| <= 2^32 raw) by 2^-shift to below 2^29, so that the second moments
    // stay below 3·2^58 and keep 29 bits of the spread whatever its size.
    int64_t dx[3] = {0, 0, 0}, dy[3] = {0, 0, 0};
    int shift = 0;
    for (int i = 0; i < count; ++i) {
        dx[i] = px[i] - mx;
        dy[i] = py[i] - my;
        while (abs64(dx[i]) >> shift >= pow2(29) || abs64(dy[i]) >> shift >= pow2(29)) ++shift;
    }
    int64_t cxx = 0, cyy = 0, cxy = 0, spread2 = 0;
    for (int i = 0; i < count; ++i) {
        dx[i] = shr_round_half_away(dx[i], shift);
        dy[i] = shr_round_half_away(dy[i], shift);
        cxx += dx[i] * dx[i];
        cyy += dy[i] * dy[i];
        cxy += dx[i] * dy[i];
    }
    for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j) {
            const int64_t ex = dx[i] - dx[j], ey = dy[i] - dy[j];
            if (ex * ex + ey * ey > spread2) spread2 = ex * ex + ey * ey;
        }
    // Points closer together than min_spread give a less certain direction than the polar line
    // of the farthest filter (and none at all when they coincide).
    const int64_t min_spread = params_.min_spread.raw >> shift;
    if (spread2 < min_spread * min_spread) return polar_line(farthest_filter());
    // Principal axis: φ = ½·atan2(2·Cxy, Cxx − Cyy), minimising the squared perpendicular
    // distances; the normal is φ + 90°.
    int64_t a = 2 * cxy, b = cxx - cyy;
    while (abs64(a) >= pow2(30) || abs64(b) >= pow2(30)) {
        a = shr_round_half_away(a, 1);
        b = shr_round_half_away(b, 1);
    }
    const angle_t phi = atan2_angle(static_cast<int32_t>(a), static_cast<int32_t>(b)) / 2;
    const angle_t theta = phi + kAngleQuarterTurn;
    const SinCos n = sin_cos(theta);
    return finish(theta, dot_normal(n, q16_16::from_raw(mx), q16_16::from_raw(my)));
}

}  // namespace qt

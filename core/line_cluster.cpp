#include "line_cluster.h"

#include "isqrt.h"
#include "line_fit.h"

namespace qt {

namespace {

int64_t sq(int64_t v) { return v * v; }

// Pixels (q16_16) to 1/32 pixel, rounded.
int32_t to32(q16_16 v) { return static_cast<int32_t>(shr_round_half_away(v.raw, 11)); }

// Gap between b and a along a's direction, q16_16 pixels; 0 when they overlap.
int64_t gap_along(const Segment& a, const Segment& b) {
    const int64_t ux = static_cast<int64_t>(a.x2.raw) - a.x1.raw, uy = static_cast<int64_t>(a.y2.raw) - a.y1.raw;
    const int64_t len = isqrt64(static_cast<uint64_t>(ux * ux + uy * uy));  // q16_16
    if (len == 0) return 0;
    auto t = [&](q16_16 x, q16_16 y) {  // position along a from its first end, q16_16
        return ((static_cast<int64_t>(x.raw) - a.x1.raw) * ux + (static_cast<int64_t>(y.raw) - a.y1.raw) * uy) / len;
    };
    const int64_t t1 = t(b.x1, b.y1), t2 = t(b.x2, b.y2);
    const int64_t lo = t1 < t2 ? t1 : t2, hi = t1 < t2 ? t2 : t1;
    return hi < 0 ? -hi : lo > len ? lo - len : 0;
}

bool similar(const Segment& a, const Segment& b, const ClusterParams& p) {
    const int64_t d2 = sq(static_cast<int64_t>(a.cx.raw) - b.cx.raw) + sq(static_cast<int64_t>(a.cy.raw) - b.cy.raw);
    return d2 <= sq(p.distance.raw) && orientation_difference(a.theta, b.theta) <= p.max_angle &&
           gap_along(a, b) <= p.gap.raw;
}

}  // namespace

angle_t orientation_difference(angle_t a, angle_t b) {
    const angle_t d = (a - b) & (kAngleHalfTurn - 1u);  // modulo 180°
    return d > kAngleQuarterTurn ? kAngleHalfTurn - d : d;
}

Status cluster_segments(const Segment* in, uint16_t n, const ClusterParams& params,
                        uint8_t* scratch, Segment* out, uint16_t capacity, uint16_t* count,
                        ClusterStats* stats) {
    *count = 0;
    *stats = ClusterStats{};
    if (n > 255) return Status::bad_size;
    constexpr uint8_t kFree = 0xFF;
    for (uint16_t i = 0; i < n; ++i) scratch[i] = kFree;
    for (;;) {
        int32_t seed = -1;
        for (uint16_t i = 0; i < n; ++i)
            if (scratch[i] == kFree && (seed < 0 || in[i].points > in[seed].points)) seed = i;
        if (seed < 0) break;
        const uint8_t id = static_cast<uint8_t>(stats->clusters + stats->clusters_dropped);
        for (uint16_t i = 0; i < n; ++i)
            if (scratch[i] == kFree && similar(in[seed], in[i], params)) scratch[i] = id;
        scratch[seed] = id;

        // Refit from the members, coordinates relative to the seed's first end (1/32 px).
        const int32_t ax = to32(in[seed].x1), ay = to32(in[seed].y1);
        Moments m;
        uint32_t points = 0;
        for (uint16_t i = 0; i < n; ++i) {
            if (scratch[i] != id) continue;
            const Segment& s = in[i];
            const int32_t x1 = to32(s.x1) - ax, y1 = to32(s.y1) - ay;
            const int32_t x2 = to32(s.x2) - ax, y2 = to32(s.y2) - ay;
            const int32_t w = s.points > 0 ? s.points : 1;
            m.add((x1 + x2) / 2, (y1 + y2) / 2, w);
            m.add_spread(x2 - x1, y2 - y1, w);
            points += s.points;
        }
        FittedLine line;
        fit_line(m, ax, ay, line);
        q16_16 lo = along(line, in[seed].x1, in[seed].y1), hi = lo;
        for (uint16_t i = 0; i < n; ++i) {
            if (scratch[i] != id) continue;
            const q16_16 t1 = along(line, in[i].x1, in[i].y1), t2 = along(line, in[i].x2, in[i].y2);
            lo = t1 < lo ? t1 : lo;
            lo = t2 < lo ? t2 : lo;
            hi = t1 > hi ? t1 : hi;
            hi = t2 > hi ? t2 : hi;
        }
        if (*count < capacity) {
            out[(*count)++] = make_segment(line, lo, hi, static_cast<uint16_t>(points > 65535 ? 65535 : points));
            ++stats->clusters;
        } else {
            ++stats->clusters_dropped;
        }
    }
    return Status::ok;
}

}  // namespace qt

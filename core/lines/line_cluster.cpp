#include "lines/line_cluster.h"

#include "base/isqrt.h"
#include "lines/line_fit.h"

namespace qt {

namespace {

int64_t sq(int64_t v) { return v * v; }

// Pixels (q16_16) to 1/32 pixel, rounded.
int32_t to32(q16_16 v) { return static_cast<int32_t>(shr_round_half_away(v.raw, 11)); }

// Gap between b and a along a's direction, q16_16 pixels; 0 when they overlap.
int64_t gap_along(const Segment& a, const Segment& b) {
    const int64_t ux = static_cast<int64_t>(a.x2.raw) - a.x1.raw,
                  uy = static_cast<int64_t>(a.y2.raw) - a.y1.raw;
    const int64_t len = isqrt64(static_cast<uint64_t>(ux * ux + uy * uy));  // q16_16
    if (len == 0) return 0;
    auto t = [&](q16_16 x, q16_16 y) {  // position along a from its first end, q16_16
        return ((static_cast<int64_t>(x.raw) - a.x1.raw) * ux +
                (static_cast<int64_t>(y.raw) - a.y1.raw) * uy) /
               len;
    };
    const int64_t t1 = t(b.x1, b.y1), t2 = t(b.x2, b.y2);
    const int64_t lo = t1 < t2 ? t1 : t2, hi = t1 < t2 ? t2 : t1;
    return hi < 0 ? -hi : lo > len ? lo - len : 0;
}

// Whether both ends of the shorter segment lie within `offset` of the longer one's line.
// Worked in 1/32 px, so that any q16_16 coordinates keep the products within 64 bits.
bool on_one_line(const Segment& a, const Segment& b, q16_16 offset) {
    const int64_t adx = to32(a.x2) - to32(a.x1), ady = to32(a.y2) - to32(a.y1);
    const int64_t bdx = to32(b.x2) - to32(b.x1), bdy = to32(b.y2) - to32(b.y1);
    const bool a_longer = adx * adx + ady * ady >= bdx * bdx + bdy * bdy;
    const Segment& l = a_longer ? a : b;
    const Segment& s = a_longer ? b : a;
    const int64_t dx = a_longer ? adx : bdx, dy = a_longer ? ady : bdy;
    const int64_t len = isqrt64(static_cast<uint64_t>(dx * dx + dy * dy));  // 1/32 px
    const int64_t reach = shr_round_half_away(offset.raw, 11) * len;        // offset·len
    auto off = [&](q16_16 x, q16_16 y) {  // distance from l's line, times len
        const int64_t c = (to32(x) - to32(l.x1)) * dy - (to32(y) - to32(l.y1)) * dx;
        return c < 0 ? -c : c;
    };
    return off(s.x1, s.y1) <= reach && off(s.x2, s.y2) <= reach;
}

bool similar(const Segment& a, const Segment& b, const ClusterParams& p) {
    const int64_t d2 = sq(static_cast<int64_t>(a.cx.raw) - b.cx.raw) +
                       sq(static_cast<int64_t>(a.cy.raw) - b.cy.raw);
    return d2 <= sq(p.distance.raw) && orientation_difference(a.theta, b.theta) <= p.max_angle &&
           gap_along(a, b) <= p.gap.raw && on_one_line(a, b, p.offset);
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
            Segment& merged = out[(*count)++];
            merged =
                make_segment(line, lo, hi, static_cast<uint16_t>(points > 65535 ? 65535 : points));
            // The seed's polarity, turned with the normal when the refit flipped it (the
            // orientations agree within max_angle, so the normals are ~0° or ~180° apart).
            const angle_t turn = merged.theta - in[seed].theta;
            const bool flipped = turn > kAngleQuarterTurn && turn < 3u * kAngleQuarterTurn;
            merged.bright_side =
                static_cast<int8_t>(flipped ? -in[seed].bright_side : in[seed].bright_side);
            ++stats->clusters;
        } else {
            ++stats->clusters_dropped;
        }
    }
    return Status::ok;
}

}  // namespace qt

namespace qt {

namespace {

// Intersection of the lines through segments a and b, in q16_16; false when (near) parallel.
// Computed in 1/256 pixel so that the products stay within 64 bits (coordinates < 2^19,
// cross products < 2^39, their products with a direction < 2^58).
bool intersect(const Segment& a, const Segment& b, q16_16& x, q16_16& y) {
    auto q8 = [](q16_16 v) { return shr_round_half_away(v.raw, 8); };
    const int64_t ax = q8(a.x1), ay = q8(a.y1), dax = q8(a.x2) - ax, day = q8(a.y2) - ay;
    const int64_t bx = q8(b.x1), by = q8(b.y1), dbx = q8(b.x2) - bx, dby = q8(b.y2) - by;
    const int64_t denom = dax * dby - day * dbx;
    if (denom == 0) return false;
    const int64_t num = (bx - ax) * dby - (by - ay) * dbx;  // t = num / denom along a
    x = q16_16::from_raw((ax + div_round_half_away(dax * num, denom)) * 256);
    y = q16_16::from_raw((ay + div_round_half_away(day * num, denom)) * 256);
    return true;
}

int64_t dist2(q16_16 x1, q16_16 y1, q16_16 x2, q16_16 y2) {
    return sq(static_cast<int64_t>(x1.raw) - x2.raw) + sq(static_cast<int64_t>(y1.raw) - y2.raw);
}

}  // namespace

uint16_t join_corners(Segment* lines, uint16_t n, const CornerParams& params,
                      CornerCandidate* best) {
    // best[2i] and best[2i + 1]: line i's first and second end. Ends move only after every
    // pair is seen, so the order of the pairs does not matter.
    const int64_t reach = sq(params.max_distance.raw);
    for (uint32_t e = 0; e < 2u * n; ++e) best[e] = CornerCandidate{reach + 1, {}, {}};
    for (uint16_t i = 0; i < n; ++i)
        for (uint16_t j = static_cast<uint16_t>(i + 1); j < n; ++j) {
            const angle_t d = orientation_difference(lines[i].theta, lines[j].theta);
            if (d < params.min_angle) continue;
            q16_16 x, y;
            if (!intersect(lines[i], lines[j], x, y)) continue;
            const int64_t di1 = dist2(x, y, lines[i].x1, lines[i].y1),
                          di2 = dist2(x, y, lines[i].x2, lines[i].y2);
            const int64_t dj1 = dist2(x, y, lines[j].x1, lines[j].y1),
                          dj2 = dist2(x, y, lines[j].x2, lines[j].y2);
            const uint16_t ei = static_cast<uint16_t>(2 * i + (di2 < di1 ? 1 : 0));
            const uint16_t ej = static_cast<uint16_t>(2 * j + (dj2 < dj1 ? 1 : 0));
            const int64_t di = di2 < di1 ? di2 : di1, dj = dj2 < dj1 ? dj2 : dj1;
            if (di > reach || dj > reach) continue;  // a corner of both lines, or of neither
            if (di < best[ei].distance2) best[ei] = CornerCandidate{di, x, y};
            if (dj < best[ej].distance2) best[ej] = CornerCandidate{dj, x, y};
        }
    uint16_t moved = 0;
    for (uint32_t e = 0; e < 2u * n; ++e) {
        if (best[e].distance2 > reach) continue;
        Segment& l = lines[e / 2];
        if (e % 2 == 0) {
            l.x1 = best[e].x;
            l.y1 = best[e].y;
        } else {
            l.x2 = best[e].x;
            l.y2 = best[e].y;
        }
        ++moved;
    }
    return moved;
}

}  // namespace qt

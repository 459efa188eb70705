#include "quad_detector.h"

namespace qt {

namespace {

// Distance of the middle of segment s from line l with normal n, pixels, q16_16.
int64_t separation(const Segment& l, SinCos n, const Segment& s) {
    const int64_t d = signed_distance(l, n, (static_cast<int64_t>(s.x1.raw) + s.x2.raw) / 2,
                                      (static_cast<int64_t>(s.y1.raw) + s.y2.raw) / 2);
    return d < 0 ? -d : d;
}

int64_t perimeter(const Quad& q) {
    int64_t sum = 0;
    for (int i = 0; i < 4; ++i) sum += distance(q.corners[i], q.corners[(i + 1) & 3]).raw;
    return sum;
}

// Length of side a -> b (on lines[on]) covered by the lines lying along it: `on` itself and
// every line with both ends within collinear_distance of it; at most the side's length.
int64_t side_support(Point16 a, Point16 b, const Segment* lines, const SinCos* normals, uint16_t n, uint8_t on,
                     int64_t side_length, const QuadParams& p) {
    const Segment& l = lines[on];
    const SinCos nl = normals[on];
    auto off_line = [&](q16_16 x, q16_16 y) {  // pixels, q16_16
        const int64_t d = signed_distance(l, nl, x.raw, y.raw);
        return d < 0 ? -d : d;
    };
    int64_t covered = 0;
    for (uint16_t j = 0; j < n; ++j) {
        const Segment& s = lines[j];
        if (j != on && (off_line(s.x1, s.y1) > p.collinear_distance.raw || off_line(s.x2, s.y2) > p.collinear_distance.raw))
            continue;
        covered += side_overlap(a, b, s).raw;
    }
    return covered < side_length ? covered : side_length;
}

// Whether every corner of a lies within `tolerance` (per axis) of the same corner of b.
bool same_quad(const Quad& a, const Quad& b, q16_16 tolerance) {
    for (int i = 0; i < 4; ++i) {
        const int64_t dx = static_cast<int64_t>(a.corners[i].x.raw) - b.corners[i].x.raw;
        const int64_t dy = static_cast<int64_t>(a.corners[i].y.raw) - b.corners[i].y.raw;
        if (dx > tolerance.raw || dx < -tolerance.raw || dy > tolerance.raw || dy < -tolerance.raw) return false;
    }
    return true;
}

// Strict "a ranks before b": score, then perimeter, then line indices.
bool ranks_before(const Quad& a, int64_t perim_a, const Quad& b, int64_t perim_b) {
    if (a.score != b.score) return a.score > b.score;
    if (perim_a != perim_b) return perim_a > perim_b;
    for (int i = 0; i < 4; ++i)
        if (a.lines[i] != b.lines[i]) return a.lines[i] < b.lines[i];
    return false;
}

// Corners of the candidate with opposite pairs (p1, p2) and (q1, q2), put in the canonical
// order of quad_rules.h. False when two lines do not cross or the shape is not convex.
bool build_candidate(const Segment* lines, const SinCos* normals, LinePair p, LinePair q, Quad& out) {
    // Going round: p1 ∩ q1, q1 ∩ p2, p2 ∩ q2, q2 ∩ p1; side i runs from corner i to i + 1.
    const uint8_t side_line[4] = {q.a, p.b, q.b, p.a};
    Point16 c[4];
    for (int i = 0; i < 4; ++i) {
        const uint8_t before = side_line[(i + 3) & 3], after = side_line[i];
        if (!intersect_lines(lines[before], normals[before], lines[after], normals[after], c[i])) return false;
    }
    if (!is_convex(c)) return false;

    // Anti-clockwise as seen (negative shoelace in y-down); reversing the corner order
    // c0 c3 c2 c1 reverses the sides too: L3 L2 L1 L0.
    Point16 ordered[4];
    uint8_t ordered_line[4];
    const bool reverse = shoelace2(c) > 0;
    for (int i = 0; i < 4; ++i) {
        ordered[i] = reverse ? c[(4 - i) & 3] : c[i];
        ordered_line[i] = reverse ? side_line[3 - i] : side_line[i];
    }
    int first = 0;
    for (int i = 1; i < 4; ++i) {
        const int64_t s = static_cast<int64_t>(ordered[i].x.raw) + ordered[i].y.raw;
        const int64_t best = static_cast<int64_t>(ordered[first].x.raw) + ordered[first].y.raw;
        if (s < best) first = i;
    }
    for (int i = 0; i < 4; ++i) {
        out.corners[i] = ordered[(i + first) & 3];
        out.lines[i] = ordered_line[(i + first) & 3];
    }
    return true;
}

}  // namespace

Status detect_quads(const Segment* lines, uint16_t n, uint16_t width, uint16_t height,
                    const QuadParams& params, LinePair* pairs, uint16_t pair_capacity, SinCos* normals, Quad* out,
                    uint16_t capacity, uint16_t* count, QuadStats* stats) {
    *count = 0;
    *stats = QuadStats{};
    if (n > 255 || width == 0 || height == 0) return Status::bad_size;

    // Parallel pairs (rule 1) whose lines are at least half the shortest side apart: a side
    // meets its parallel pair at more than 90° − perpendicular_tolerance, so it is at most
    // ~1/sin(55°) times their separation; half is a safe prefilter, rule 4 decides later.
    uint16_t npairs = 0;
    const int64_t min_sep = params.min_side_length.raw / 2, max_sep = params.max_side_length.raw;
    for (uint16_t i = 0; i < n; ++i) normals[i] = sin_cos(lines[i].theta);
    for (uint16_t i = 0; i < n; ++i) {
        const SinCos normal = normals[i];
        for (uint16_t j = static_cast<uint16_t>(i + 1); j < n; ++j) {
            if (!rule_parallel(lines[i].theta, lines[j].theta, params)) continue;
            const int64_t sep = separation(lines[i], normal, lines[j]);
            if (sep < min_sep || sep > max_sep) continue;
            if (npairs == pair_capacity) {
                ++stats->pairs_dropped;
                continue;
            }
            pairs[npairs++] = {static_cast<uint8_t>(i), static_cast<uint8_t>(j)};
        }
    }
    stats->parallel_pairs = npairs;

    for (uint16_t i = 0; i < npairs; ++i) {
        for (uint16_t j = static_cast<uint16_t>(i + 1); j < npairs; ++j) {
            const LinePair p = pairs[i], q = pairs[j];
            if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;
            ++stats->combinations;
            const angle_t pa = lines[p.a].theta, pb = lines[p.b].theta;
            const angle_t qa = lines[q.a].theta, qb = lines[q.b].theta;
            if (!rule_perpendicular(pa, qa, params) || !rule_perpendicular(pa, qb, params) ||
                !rule_perpendicular(pb, qa, params) || !rule_perpendicular(pb, qb, params)) {
                ++stats->rejected_perpendicular;
                continue;
            }
            Quad cand;
            if (!build_candidate(lines, normals, p, q, cand)) {
                ++stats->rejected_shape;
                continue;
            }
            const Segment* side_lines[4] = {&lines[cand.lines[0]], &lines[cand.lines[1]], &lines[cand.lines[2]],
                                            &lines[cand.lines[3]]};
            const SinCos side_normals[4] = {normals[cand.lines[0]], normals[cand.lines[1]], normals[cand.lines[2]],
                                            normals[cand.lines[3]]};
            if (!rule_contrast(cand.corners, side_lines, side_normals, params)) {
                ++stats->rejected_contrast;
                continue;
            }
            if (!rule_corners_inside(cand.corners, width, height, params)) {
                ++stats->rejected_inside;
                continue;
            }
            q16_16 sides[4];
            for (int k = 0; k < 4; ++k) sides[k] = distance(cand.corners[k], cand.corners[(k + 1) & 3]);
            if (!rule_side_lengths(sides, params)) {
                ++stats->rejected_sides;
                continue;
            }
            if (!rule_aspect(sides, params)) {
                ++stats->rejected_aspect;
                continue;
            }
            // Support: each side covered at least min_side_coverage; score = covered share of
            // the perimeter. Sides <= 2048 px, so the q16_16 sums stay below 2^31.
            int64_t covered = 0, perim = 0;
            bool supported = true;
            for (int k = 0; k < 4; ++k) {
                const int64_t o = side_support(cand.corners[k], cand.corners[(k + 1) & 3], lines, normals, n,
                                               cand.lines[k], sides[k].raw, params);
                if (o * 65536 < static_cast<int64_t>(sides[k].raw) * params.min_side_coverage.raw) supported = false;
                covered += o;
                perim += sides[k].raw;
            }
            cand.score = q16_16::from_raw(perim > 0 ? (covered << 16) / perim : 0);  // rounded down
            if (!supported || cand.score < params.min_score) {
                ++stats->rejected_support;
                continue;
            }
            ++stats->accepted;

            // One quadrangle found twice (a side on two collinear lines, say) is reported once,
            // as its better-ranked candidate.
            if (capacity == 0) continue;
            uint16_t dup = 0;
            while (dup < *count && !same_quad(out[dup], cand, params.collinear_distance)) ++dup;
            if (dup < *count) {
                if (!ranks_before(cand, perim, out[dup], perimeter(out[dup]))) continue;
                for (uint16_t k = dup; k + 1u < *count; ++k) out[k] = out[k + 1];
                --*count;
            }
            // Keep the best `capacity`, in rank order (insertion; capacity is small).
            if (*count == capacity && !ranks_before(cand, perim, out[capacity - 1], perimeter(out[capacity - 1])))
                continue;
            uint16_t at = *count < capacity ? *count : static_cast<uint16_t>(capacity - 1);
            while (at > 0 && ranks_before(cand, perim, out[at - 1], perimeter(out[at - 1]))) {
                out[at] = out[at - 1];
                --at;
            }
            out[at] = cand;
            if (*count < capacity) ++*count;
        }
    }
    stats->quads = *count;
    return stats->pairs_dropped > 0 ? Status::capacity_exceeded : Status::ok;
}

}  // namespace qt

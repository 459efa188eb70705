#include "quads/quad_refine.h"

#include "gradient/gradient_word.h"
#include "lines/line_fit.h"
#include "quads/quad_rules.h"

namespace qt {

namespace {

// A line walked along: origin (1/32 px), unit direction u (q2_30) and the stretch between the
// positions t0 < t1 along u from the origin (1/32 px).
struct Walk {
    int32_t ox32, oy32;
    int32_t ux, uy;
    int32_t t0, t1;
};

int32_t to32(q16_16 v) {
    return static_cast<int32_t>(shr_round_half_away(v.raw, 11));
}  // q16.16 -> 1/32 px

int32_t abs32(int32_t v) { return v < 0 ? -v : v; }

constexpr int32_t kMaxSteps = 2048;  // pixels along a side: frames up to 2048 px wide and high

// The side's gradient direction bin (dark to bright across it) and whether the polarity is
// known: the line's bright side lies along its normal θ (bright_side > 0) or against it.
struct Polarity {
    uint32_t bin;
    bool known;
};

Polarity polarity_of(const Segment& line) {
    const SinCos n = sin_cos(line.theta);
    const int32_t sign = line.bright_side < 0 ? -1 : 1;
    // q2_30 -> ±2^16: direction_bin needs (lo << 8) to fit 32 bits.
    return {direction_bin(sign * (n.cos.raw >> 14), sign * (n.sin.raw >> 14)),
            line.bright_side != 0};
}

bool along_side(uint32_t dir, Polarity p) {
    if (p.known) {
        const uint32_t d = (dir - p.bin) & 15u;
        return d <= 2u || d >= 14u;
    }
    const uint32_t d = (dir - p.bin) & 7u;
    return d <= 2u || d >= 6u;
}

uint32_t popcount32(uint32_t v) {  // bits set, SWAR (no population count instruction on M3/M4)
    v = v - ((v >> 1) & 0x55555555u);
    v = (v & 0x33333333u) + ((v >> 2) & 0x33333333u);
    v = (v + (v >> 4)) & 0x0F0F0F0Fu;
    return (v * 0x01010101u) >> 24;
}

// Whether any of bits [lo, hi) of the bit set `marks` is set.
bool marks_in(const uint32_t* marks, uint32_t lo, uint32_t hi) {
    while (lo < hi) {
        const uint32_t word = lo >> 5, bit = lo & 31u;
        const uint32_t span = hi - lo < 32u - bit ? hi - lo : 32u - bit;  // bits in this word
        const uint32_t mask = (span == 32u ? ~0u : ((1u << span) - 1u)) << bit;
        if (marks[word] & mask) return true;
        lo += span;
    }
    return false;
}

// A step between two held steps counts as held: a full edge list keeps every other step of
// its weaker edges (edge_list.h), and a side seen through that thinning is a whole side.
// In place, a word of marks at a time; a gap of two steps or more stays.
void fill_single_gaps(uint32_t* marks, uint32_t words) {
    uint32_t previous = 0;  // the word before, as it was
    for (uint32_t j = 0; j < words; ++j) {
        const uint32_t word = marks[j];
        const uint32_t before = (word << 1) | (previous >> 31);
        const uint32_t after = (word >> 1) | (j + 1 < words ? marks[j + 1] << 31 : 0u);
        marks[j] = word | (before & after);
        previous = word;
    }
}

// Adds to m (coordinates relative to the walk's origin) every edge point within band32 of the
// walk's line between t0 and t1 whose gradient runs across the line with the side's polarity;
// returns the major-axis steps (pixel columns of a side nearer horizontal, rows otherwise)
// that held at least one such point and sets *steps to the steps the stretch spans. The edge
// list is searched a row at a time (one search per row, not per pixel).
uint32_t gather(const EdgeList& edges, const Walk& w, int32_t band32, Polarity pol, Moments& m,
                uint32_t* steps, uint8_t* ends) {
    const bool major_is_y = abs32(w.uy) > abs32(w.ux);
    const int64_t u_major = major_is_y ? w.uy : w.ux, u_minor = major_is_y ? w.ux : w.uy;
    const int32_t o_major = major_is_y ? w.oy32 : w.ox32, o_minor = major_is_y ? w.ox32 : w.oy32;
    // Major coordinates of the stretch's ends, whole pixels, in increasing order.
    int64_t m0 = o_major + ((static_cast<int64_t>(w.t0) * u_major) >> 30);
    int64_t m1 = o_major + ((static_cast<int64_t>(w.t1) * u_major) >> 30);
    if (m0 > m1) {
        const int64_t t = m0;
        m0 = m1;
        m1 = t;
    }
    const int32_t first = static_cast<int32_t>((m0 + 31) >> 5);
    int32_t last = static_cast<int32_t>(m1 >> 5);
    if (last - first >= kMaxSteps) last = first + kMaxSteps - 1;
    *steps = last >= first ? static_cast<uint32_t>(last - first + 1) : 0u;
    *ends = 0;
    if (*steps == 0) return 0;
    // Minor-axis half window: band / |u_major| (|u_major| >= 1/√2), whole pixels, plus one.
    const int32_t reach =
        static_cast<int32_t>(
            ((static_cast<int64_t>(band32) << 30) / (u_major < 0 ? -u_major : u_major)) >> 5) +
        1;
    // Slopes in q16.16, one division each (a 64-bit division is a library call on Cortex-M):
    // minor per major (|.| <= 1) and major per minor (0 when the line runs along a row or
    // column within 2^-14, where every column of the stretch is searched).
    const int64_t slope = (u_minor * 65536) / u_major;
    const int64_t inverse =
        (u_minor < 0 ? -u_minor : u_minor) >= (int64_t{1} << 16) ? (u_major * 65536) / u_minor : 0;
    auto minor_at =
        [&](int32_t major) {  // the line's minor coordinate at a major one, whole pixels
            return static_cast<int32_t>(
                (o_minor + ((static_cast<int64_t>(major * 32 - o_major) * slope) >> 16) + 16) >> 5);
        };
    uint32_t marks[kMaxSteps / 32] = {};  // bit k: step first + k holds a point
    auto consider = [&](uint32_t i, int32_t major) {
        const edge_point p = edges[static_cast<uint16_t>(i)];
        if (major < first || major > last || !along_side(ep::dir(p), pol)) return;
        // |dx|, |dy| < 2^21 (1/32 px; the origin is a corner near the frame), so the distance
        // across, < 2^22 after the shift, is formed from two 32 x 32 -> 64-bit products.
        const int32_t dx = ep::x32(p) - w.ox32, dy = ep::y32(p) - w.oy32;
        const int32_t d =
            static_cast<int32_t>((static_cast<int64_t>(dx) * -static_cast<int64_t>(w.uy) +
                                  static_cast<int64_t>(dy) * w.ux) >>
                                 30);  // across, 1/32 px
        if (d > band32 || d < -band32) return;
        m.add(dx, dy);
        const uint32_t k = static_cast<uint32_t>(major - first);
        marks[k >> 5] |= 1u << (k & 31u);
    };
    uint32_t a = 0, b = 0;
    if (major_is_y) {
        for (int32_t y = first; y <= last; ++y) {
            const int32_t centre = minor_at(y);
            edges.span(centre - reach, centre + reach, y, &a, &b);
            for (uint32_t i = a; i < b; ++i) consider(i, y);
        }
    } else {
        // Rows the band crosses; in each, the columns where the line is within `reach` rows.
        const int32_t ya = minor_at(first), yb = minor_at(last);
        const int32_t lo = (ya < yb ? ya : yb) - reach, hi = (ya < yb ? yb : ya) + reach;
        for (int32_t y = lo; y <= hi; ++y) {
            int32_t x_lo = first, x_hi = last;
            if (inverse != 0) {
                const int64_t xa =
                    o_major + ((static_cast<int64_t>((y - reach) * 32 - o_minor) * inverse) >> 16);
                const int64_t xb =
                    o_major + ((static_cast<int64_t>((y + reach) * 32 - o_minor) * inverse) >> 16);
                const int64_t l = ((xa < xb ? xa : xb) >> 5) - 1,
                              h = ((xa < xb ? xb : xa) >> 5) + 1;
                x_lo = l > first ? static_cast<int32_t>(l) : first;
                x_hi = h < last ? static_cast<int32_t>(h) : last;
            }
            if (x_lo > x_hi) continue;
            edges.span(x_lo, x_hi, y, &a, &b);
            for (uint32_t i = a; i < b; ++i)
                consider(i, static_cast<int32_t>(ep::x(edges[static_cast<uint16_t>(i)])));
        }
    }
    // Steps holding a point, and whether any lies in the first or the last quarter of them
    // (a word of marks at a time; no mark lies at or beyond *steps).
    uint32_t held = 0;
    const uint32_t quarter = *steps / 4, words = (*steps + 31u) / 32u;
    fill_single_gaps(marks, words);
    for (uint32_t j = 0; j < words; ++j) held += popcount32(marks[j]);
    if (marks_in(marks, 0, quarter)) *ends |= 1u;
    if (marks_in(marks, *steps - quarter, *steps)) *ends |= 2u;
    // The walk may run either way along the side: bit 0 is the end at the walk's origin.
    if ((major_is_y ? w.uy : w.ux) < 0)
        *ends = static_cast<uint8_t>(((*ends & 1u) << 1) | (*ends >> 1));
    return held;
}

// The walk along the line from corner a towards b (len = |ab| in q16_16, > 0) over [t0, t1].
Walk walk_from(Point16 a, Point16 b, int64_t len, int32_t t0, int32_t t1) {
    return {to32(a.x),
            to32(a.y),
            static_cast<int32_t>(((static_cast<int64_t>(b.x.raw) - a.x.raw) * (int64_t{1} << 30)) /
                                 len),
            static_cast<int32_t>(((static_cast<int64_t>(b.y.raw) - a.y.raw) * (int64_t{1} << 30)) /
                                 len),
            t0,
            t1};
}

// One side: the walk between corners a and b, then around the first fit. False (line left
// alone) when too few steps hold a point. *held and *steps: the evidence of the last walk.
bool refit_side(const EdgeList& edges, const Segment& line, Point16 a, Point16 b,
                const RefineParams& p, Segment& out, uint32_t* held, uint32_t* steps,
                uint8_t* ends) {
    *held = *steps = 0;
    *ends = 0;
    const int64_t len = distance(a, b).raw;  // q16_16
    const int32_t margin32 = to32(p.end_margin),
                  len32 = static_cast<int32_t>(shr_round_half_away(len, 11));
    if (len <= 0 || len32 <= 2 * margin32 + 64) return false;
    Walk w = walk_from(a, b, len, margin32, len32 - margin32);
    const Polarity pol = polarity_of(line);
    if (p.band.raw == 0) {  // refinement off: the evidence along the given line, no refit
        Moments m;
        *held = gather(edges, w, to32(p.fine_band), pol, m, steps, ends);
        return false;
    }
    FittedLine fit{};
    const int32_t bands[2] = {to32(p.band), to32(p.fine_band)};
    uint32_t n = 0;
    for (int pass = 0; pass < 2; ++pass) {
        Moments m;
        *held = gather(edges, w, bands[pass], pol, m, steps, ends);
        if (*held * 100u < *steps * p.min_share_percent || m.n < 8 ||
            !fit_line(m, w.ox32, w.oy32, fit))
            return false;
        n = static_cast<uint32_t>(m.n);
        // Next: along the fit, over the same stretch (the corners projected onto it).
        const int32_t ta = to32(along(fit, a.x, a.y)), tb = to32(along(fit, b.x, b.y));
        const int32_t lo = ta < tb ? ta : tb, hi = ta < tb ? tb : ta;
        w = Walk{to32(fit.mx), to32(fit.my), fit.dx.raw, fit.dy.raw, lo + margin32, hi - margin32};
    }
    q16_16 t1 = along(fit, line.x1, line.y1), t2 = along(fit, line.x2, line.y2);
    if (t2 < t1) {
        const q16_16 t = t1;
        t1 = t2;
        t2 = t;
    }
    out = make_segment(fit, t1, t2, static_cast<uint16_t>(n > 65535u ? 65535u : n));
    // The polarity stays with the side: flip it when the new normal points the other way.
    const SinCos before = sin_cos(line.theta), after = sin_cos(out.theta);
    const int64_t dot = static_cast<int64_t>(before.cos.raw) * after.cos.raw +
                        static_cast<int64_t>(before.sin.raw) * after.sin.raw;
    out.bright_side = static_cast<int8_t>(dot < 0 ? -line.bright_side : line.bright_side);
    return true;
}

// Side i of a verified quadrangle: evidence on both ends and on `least` % of its steps (always,
// when `least` is kCheckOff).
bool side_passes(const SideEvidence& e, int i, uint32_t least) {
    if (least == kCheckOff) return true;
    return e.steps[i] > 0 && e.ends[i] == 3u && e.held[i] * 100u >= e.steps[i] * least;
}

uint32_t least_evidence(const RefineParams& params, uint8_t completed, int i) {
    return ((static_cast<uint32_t>(completed) >> i) & 1u) != 0
               ? params.min_hidden_side_evidence_percent
               : params.min_side_evidence_percent;
}

// refine_quad's side walks, in side order, into fitted and found; the mask of sides refitted.
// After each side, go_on(found, i) false ends the walks there (the sides after it are left as
// they were given) and makes *stopped true.
template <class GoOn>
uint8_t refit_sides(const EdgeList& edges, const Segment* const lines[4],
                    const RefineParams& params, const Quad& quad, Segment fitted[4],
                    SideEvidence& found, bool* stopped, GoOn&& go_on) {
    uint8_t refitted = 0;
    *stopped = false;
    found = SideEvidence{};
    for (int i = 0; i < 4; ++i) fitted[i] = *lines[i];
    for (int i = 0; i < 4; ++i) {
        uint32_t held = 0, steps = 0;
        uint8_t ends = 0;
        if (refit_side(edges, *lines[i], quad.corners[i], quad.corners[(i + 1) & 3], params,
                       fitted[i], &held, &steps, &ends))
            refitted = static_cast<uint8_t>(refitted | (1u << i));
        found.ends[i] = ends;
        found.held[i] = static_cast<uint16_t>(held > 65535u ? 65535u : held);
        found.steps[i] = static_cast<uint16_t>(steps > 65535u ? 65535u : steps);
        if (!go_on(found, i)) {
            *stopped = true;
            break;
        }
    }
    return refitted;
}

// The rest of refine_quad once the sides are walked: corners where the refitted sides cross,
// put in detect's order with the lines, sides and evidence.
uint8_t place_refitted(const Segment* const lines[4], uint8_t refitted, const Segment fitted[4],
                       const SideEvidence& found, Quad& quad, Segment sides[4],
                       SideEvidence* evidence) {
    if (evidence) *evidence = found;
    for (int i = 0; i < 4; ++i) sides[i] = *lines[i];
    if (refitted == 0) return 0;
    Point16 c[4];
    for (int i = 0; i < 4; ++i)
        if (!intersect_lines(fitted[(i + 3) & 3], fitted[i], c[i])) return 0;
    if (!is_convex(c) || shoelace2(c) >= 0) return 0;
    int first = 0;
    for (int i = 1; i < 4; ++i)
        if (static_cast<int64_t>(c[i].x.raw) + c[i].y.raw <
            static_cast<int64_t>(c[first].x.raw) + c[first].y.raw)
            first = i;
    const uint8_t old_lines[4] = {quad.lines[0], quad.lines[1], quad.lines[2], quad.lines[3]};
    uint8_t mask = 0;
    for (int i = 0; i < 4; ++i) {
        const int k = (i + first) & 3;
        quad.corners[i] = c[k];
        quad.lines[i] = old_lines[k];
        sides[i] = fitted[k];
        mask = static_cast<uint8_t>(mask | (((static_cast<uint32_t>(refitted) >> k) & 1u) << i));
        if (evidence) {
            evidence->held[i] = found.held[k];
            evidence->steps[i] = found.steps[k];
            evidence->ends[i] = found.ends[k];
        }
    }
    return mask;
}

// Bit i: side i of q was completed (detect_quads), not found.
uint8_t completed_sides_of(const Quad& q) {
    uint8_t completed = 0;
    for (int i = 0; i < 4; ++i)
        completed = static_cast<uint8_t>(completed | ((q.lines[i] == kCompletedSide) << i));
    return completed;
}

}  // namespace

uint8_t refine_quad(const EdgeList& edges, const Segment* const lines[4],
                    const RefineParams& params, Quad& quad, Segment sides[4],
                    SideEvidence* evidence) {
    Segment fitted[4];
    SideEvidence found;
    bool stopped = false;
    const uint8_t refitted = refit_sides(edges, lines, params, quad, fitted, found, &stopped,
                                         [](const SideEvidence&, int) { return true; });
    return place_refitted(lines, refitted, fitted, found, quad, sides, evidence);
}

bool refine_verified(const EdgeList& edges, const Segment* const lines[4],
                     const RefineParams& params, Quad& quad, Segment sides[4], q16_16* score) {
    const uint8_t completed = completed_sides_of(quad);
    Segment fitted[4];
    SideEvidence found;
    bool stopped = false;
    const uint8_t refitted = refit_sides(
        edges, lines, params, quad, fitted, found, &stopped, [&](const SideEvidence& e, int i) {
            return side_passes(e, i, least_evidence(params, completed, i));
        });
    if (stopped) return false;
    SideEvidence evidence;
    place_refitted(lines, refitted, fitted, found, quad, sides, &evidence);
    // The sides may have turned with the corners.
    return verify_evidence(evidence, completed_sides_of(quad), params, score);
}

uint8_t junction_corners(const EdgeList& edges, const Point16 corners[4],
                         const RefineParams& params) {
    const int32_t margin32 = to32(params.end_margin), band32 = to32(params.fine_band);
    // runs_on[i]: bit 0, side i's line runs on past corner i; bit 1, past corner i + 1.
    uint8_t runs_on[4] = {};
    for (int i = 0; i < 4; ++i) {
        const Point16 a = corners[i], b = corners[(i + 1) & 3];
        const int64_t len = distance(a, b).raw;  // q16_16
        if (len <= 0) continue;
        const int32_t len32 = static_cast<int32_t>(shr_round_half_away(len, 11));
        const int32_t reach32 = len32 / 4 > 6 * 32 ? len32 / 4 : 6 * 32;
        const Walk along = walk_from(a, b, len, 0, 0);
        // Either polarity (a checkerboard's lines run on reversed); q2_30 -> ±2^16 as in
        // polarity_of.
        const Polarity either{direction_bin(-(along.uy >> 14), along.ux >> 14), false};
        const int32_t stretch[2][2] = {{-margin32 - reach32, -margin32},
                                       {len32 + margin32, len32 + margin32 + reach32}};
        for (int e = 0; e < 2; ++e) {
            const Walk w{along.ox32, along.oy32, along.ux, along.uy, stretch[e][0], stretch[e][1]};
            Moments m;
            uint32_t steps = 0;
            uint8_t ends = 0;
            const uint32_t held = gather(edges, w, band32, either, m, &steps, &ends);
            if (steps > 0 && 2u * held >= steps)
                runs_on[i] = static_cast<uint8_t>(runs_on[i] | (1u << e));
        }
    }
    uint8_t junctions = 0;
    for (int i = 0; i < 4; ++i)  // corner i: side i − 1 past its end and side i past its start
        junctions = static_cast<uint8_t>(junctions +
                                         (((runs_on[(i + 3) & 3] >> 1) & runs_on[i] & 1u) != 0));
    return junctions;
}

bool verify_evidence(const SideEvidence& e, uint8_t completed, const RefineParams& params,
                     q16_16* share) {
    uint32_t held = 0, steps = 0;
    bool sides_ok = true;
    for (int i = 0; i < 4; ++i) {
        held += e.held[i];
        steps += e.steps[i];
        sides_ok = sides_ok && side_passes(e, i, least_evidence(params, completed, i));
    }
    *share = q16_16::from_raw(
        steps > 0 ? static_cast<int32_t>((static_cast<int64_t>(held) << 16) / steps) : 0);
    return sides_ok && (params.min_evidence_percent == kCheckOff ||
                        held * 100u >= steps * params.min_evidence_percent);
}

}  // namespace qt

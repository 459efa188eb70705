#include "target/template_search.h"

#include "base/fixed.h"  // div_round_half_away

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

// The peak of the quadratic surface through the 3 × 3 scores s[y + 1][x + 1] about the best
// (x, y in −1..1) with the derivatives at the best by central differences: one Newton step
// −H⁻¹∇ with ∇ = (b, c), 2b = s(1, 0) − s(−1, 0), H = [2d e; e 2g], 2d = s(1, 0) − 2s(0, 0) +
// s(−1, 0), 4e = s(1, 1) − s(1, −1) − s(−1, 1) + s(−1, −1) (c, g likewise along y); the
// parabola along each axis when e = 0. In 1/256 px, each clamped to ±128. The system is
// multiplied by 4 so that every term is an integer: p = 8d, q = 4e, r = 8g, u = −4b, v = −4c.
// False (nothing written) when the surface has no maximum (p >= 0 or p·r − q² <= 0). Scores
// are Q15: |p|, |q|, |r|, |u|, |v| < 2^19, so the products stay below 2^39, and 256 times
// them below 2^47 (div_round_half_away takes up to 2^62).
bool vertex_2d_q8(const int32_t s[3][3], int32_t* dx, int32_t* dy) {
    const int64_t b2 = int64_t{s[1][2]} - s[1][0], c2 = int64_t{s[2][1]} - s[0][1];
    const int64_t d2 = int64_t{s[1][2]} - 2 * s[1][1] + s[1][0];
    const int64_t g2 = int64_t{s[2][1]} - 2 * s[1][1] + s[0][1];
    const int64_t e4 = int64_t{s[2][2]} - s[0][2] - s[2][0] + s[0][0];
    const int64_t p = 4 * d2, r = 4 * g2, q = e4, u = -2 * b2, v = -2 * c2;
    const int64_t det = p * r - q * q;
    if (p >= 0 || det <= 0) return false;
    const int64_t x = div_round_half_away(256 * (u * r - q * v), det);
    const int64_t y = div_round_half_away(256 * (p * v - q * u), det);
    *dx = static_cast<int32_t>(x < -128 ? -128 : x > 128 ? 128 : x);
    *dy = static_cast<int32_t>(y < -128 ? -128 : y > 128 ? 128 : y);
    return true;
}

// The template over the region, for every candidate top-left corner (u, v).
struct Search {
    const uint8_t* tpl;
    uint8_t tw, th;
    const PixelRegion& region;
    NccSums t;               // the template's Σa and Σa², the same at every candidate
    int32_t u0, u1, v0, v1;  // candidates' top-left corners, inclusive
    int32_t uc = 0, vc = 0;  // the window centre's placement (top-left corner)
    int64_t prior_scale = 0;  // the motion prior over the radius squared, ⌊prior_q15·2^16 / r²⌋

    // What the motion prior takes off the score of the placement (u, v), Q15: prior_q15 ·
    // (d / r)², d its distance from the centre, as ⌊prior_scale · d² / 2^16⌋ (no division per
    // placement; d <= r·√2, so at most 2·prior_q15).
    int32_t penalty(int32_t u, int32_t v) const {
        const int64_t du = u - uc, dv = v - vc;
        return static_cast<int32_t>((prior_scale * (du * du + dv * dv)) >> 16);
    }
    // Scores the placement (u, v) in full and hands it to a sink (Best or Leaders) with the
    // prior's penalty taken off.
    template <class Sink>
    void consider(int32_t u, int32_t v, Sink& sink) const {
        const int32_t raw = score(u, v);
        sink.consider(raw - penalty(u, v), u, v, raw);
    }
    // The score of the template with its top-left corner at (u, v), Q15.
    int32_t score(int32_t u, int32_t v) const {
        const uint8_t* at = region.pixels + static_cast<uint32_t>(v - region.y0) * region.stride +
                            static_cast<uint32_t>(u - region.x0);
        NccSums s = t;
        for (uint8_t y = 0; y < th; ++y)
            ncc_add_row<false>(tpl + uint32_t{y} * tw, at + uint32_t{y} * region.stride, tw, s);
        return static_cast<int32_t>(ncc_from_sums(s).q15);
    }
};

// The best score so far and where; ties go to the first candidate in row-major order, whatever
// order they are scored in.
struct Best {
    int32_t score = INT32_MIN, u = 0, v = 0;  // score: the NCC less the motion prior's penalty
    int32_t ncc = 0;                          // the best's own NCC, Q15
    uint32_t positions = 0;                   // candidates scored or ruled out
    int32_t bar() const { return score; }     // what a candidate must reach to count
    static bool before(int32_t s, int32_t cu, int32_t cv, int32_t than_s, int32_t than_u,
                       int32_t than_v) {
        return s > than_s || (s == than_s && (cv < than_v || (cv == than_v && cu < than_u)));
    }
    void consider(int32_t s, int32_t cu, int32_t cv, int32_t raw) {
        ++positions;
        if (before(s, cu, cv, score, u, v)) {
            score = s;
            u = cu;
            v = cv;
            ncc = raw;
        }
    }
};

// The kLeaders best placements of a coarse pass, in the order of Best (the first the best).
constexpr int kLeaders = 3;
struct Leaders {
    Best at[kLeaders];
    uint32_t positions = 0;
    // The score a candidate must reach to enter (the last leader's; INT32_MIN while not full).
    int32_t bar() const { return at[kLeaders - 1].score; }
    void consider(int32_t s, int32_t cu, int32_t cv, int32_t raw) {
        ++positions;
        int k = kLeaders;
        while (k > 0 && Best::before(s, cu, cv, at[k - 1].score, at[k - 1].u, at[k - 1].v)) --k;
        if (k == kLeaders) return;
        for (int j = kLeaders - 1; j > k; --j) at[j] = at[j - 1];
        at[k].score = s;
        at[k].u = cu;
        at[k].v = cv;
        at[k].ncc = raw;
    }
};

// The candidates' columns [u0, u1 + tw) in strips of at most kStrip: Σb and Σb² of each
// placement from sums over its columns (each column's th pixels, slid down the rows of
// placements), so that a placement costs only its Σab (one multiply-add a pixel). The NccSums
// are those Search::score() adds up pixel by pixel: the same scores, the same best. Placements
// (u0 + i·step, v0 + j·step) only; Sink is Best or Leaders.
constexpr int32_t kStrip = 64;

// Windows of at most this many placements are searched whole at any step: the coarse pass and
// the leaders' neighbours would score about as many.
constexpr int64_t kExhaustiveUpTo = 49;

template <class Sink>
void scan_strips(const Search& q, int32_t step, Sink& best) {
    const uint8_t tw = q.tw, th = q.th;
    uint32_t col_sum[kStrip], col_sq[kStrip];
    // Strips start on the lattice and hold whole placements: kStrip − tw + 1 of them at most.
    const int32_t span = (kStrip - tw + 1) / step * step;
    for (int32_t s0 = q.u0; s0 <= q.u1; s0 += span) {
        const int32_t s1 = q.u1 < s0 + span - 1 ? q.u1 : s0 + span - 1;  // last placement
        const int32_t cols = s1 - s0 + tw;
        const uint8_t* left = q.region.pixels + static_cast<uint32_t>(s0 - q.region.x0);
        auto row_at = [&](int32_t r) {
            return left + static_cast<uint32_t>(r - q.region.y0) * q.region.stride;
        };
        auto add_row = [&](int32_t r) {
            const uint8_t* in = row_at(r);
            for (int32_t c = 0; c < cols; ++c) {
                col_sum[c] += in[c];
                col_sq[c] += uint32_t{in[c]} * in[c];
            }
        };
        auto remove_row = [&](int32_t r) {
            const uint8_t* out = row_at(r);
            for (int32_t c = 0; c < cols; ++c) {
                col_sum[c] -= out[c];
                col_sq[c] -= uint32_t{out[c]} * out[c];
            }
        };
        // The columns hold rows [v, v + th) for each row v of placements: the first's rows,
        // then each step's rows in and out.
        for (int32_t c = 0; c < cols; ++c) col_sum[c] = col_sq[c] = 0;
        for (int32_t r = q.v0; r < q.v0 + th; ++r) add_row(r);
        for (int32_t v = q.v0; v <= q.v1; v += step) {
            if (v > q.v0)
                for (int32_t r = v - step; r < v; ++r) {
                    remove_row(r);
                    add_row(r + th);
                }
            uint32_t box_sum = 0, box_sq = 0;
            for (int32_t c = 0; c < tw; ++c) {
                box_sum += col_sum[c];
                box_sq += col_sq[c];
            }
            const uint8_t* at0 = row_at(v);
            for (int32_t u = s0; u <= s1; u += step) {
                const int32_t c = u - s0;
                if (u > s0)
                    for (int32_t k = c - step; k < c; ++k) {
                        box_sum += col_sum[k + tw] - col_sum[k];
                        box_sq += col_sq[k + tw] - col_sq[k];
                    }
                NccSums s = q.t;
                s.sb = box_sum;
                s.sbb = box_sq;
                s.sab = dot_block(q.tpl, tw, th, at0 + static_cast<uint32_t>(c), q.region.stride);
                // A placement whose NCC is certainly below what it needs to reach the bar (the
                // bar plus its penalty; none exceeds 32767) cannot pass it (a tie could: it may
                // come earlier in row-major order); its root and division are spared.
                const int32_t pen = q.penalty(u, v);
                const int32_t need = best.bar() == INT32_MIN ? INT32_MIN : best.bar() + pen;
                if (need > 32767 || ncc_certainly_below(s, need))
                    ++best.positions;
                else {
                    const int32_t raw = ncc_from_sums(s).q15;
                    best.consider(raw - pen, u, v, raw);
                }
            }
        }
    }
}

// The coarse-to-fine search: the lattice of every step-th placement, then the placements within
// ±(step − 1) of each of its kLeaders best, each scored once; the best of all in *best.
void coarse_to_fine(const Search& q, int32_t step, Best& best) {
    Leaders leaders;
    scan_strips(q, step, leaders);
    best.positions = leaders.positions;
    for (int k = 0; k < kLeaders && leaders.at[k].score != INT32_MIN; ++k) {
        const Best& l = leaders.at[k];
        best.consider(l.score, l.u, l.v, l.ncc);
        --best.positions;  // counted by the coarse pass
        for (int32_t v = l.v - step + 1; v < l.v + step; ++v)
            for (int32_t u = l.u - step + 1; u < l.u + step; ++u) {
                if (u < q.u0 || u > q.u1 || v < q.v0 || v > q.v1) continue;
                if ((u - q.u0) % step == 0 && (v - q.v0) % step == 0) continue;  // a lattice one
                // Scored already about an earlier leader?
                bool seen = false;
                for (int j = 0; j < k && !seen; ++j) {
                    const int32_t du = u - leaders.at[j].u, dv = v - leaders.at[j].v;
                    seen = du > -step && du < step && dv > -step && dv < step;
                }
                if (!seen) q.consider(u, v, best);
            }
    }
}

// Sub-pixel offset of the best, 1/256 px: one Newton step on the 3 × 3 scores about it when
// they are all candidates and make a maximum (a peak elongated across the axes moves both
// coordinates, which parabolas along the best row and column miss); else a parabola along each
// axis with both neighbours (0 without).
void subpixel_q8(const Search& q, const Best& best, int32_t* dx, int32_t* dy) {
    const bool inside_x = (best.u > q.u0) && (best.u < q.u1);
    const bool inside_y = (best.v > q.v0) && (best.v < q.v1);
    // The scores about the best that are candidates, s3[y + 1][x + 1]: each scored once.
    int32_t s3[3][3] = {};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const bool need = (i == 1 || inside_x) && (j == 1 || inside_y);
            if (i == 1 && j == 1)
                s3[j][i] = best.ncc;
            else if (need)
                s3[j][i] = q.score(best.u + i - 1, best.v + j - 1);
        }
    if (inside_x && inside_y && vertex_2d_q8(s3, dx, dy)) return;
    *dx = inside_x ? vertex_q8(s3[1][0], best.ncc, s3[1][2]) : 0;
    *dy = inside_y ? vertex_q8(s3[0][1], best.ncc, s3[2][1]) : 0;
}

}  // namespace

TemplateHit search_template(const uint8_t* tpl, uint8_t tw, uint8_t th, const PixelRegion& region,
                            int32_t cx, int32_t cy, uint16_t radius, uint8_t step,
                            int16_t prior_q15) {
    TemplateHit hit;
    if (tw == 0 || th == 0 || uint32_t{tw} * th > kNccMaxPixels || region.w < tw || region.h < th)
        return hit;
    // Top-left corners whose centre (u + (tw − 1)/2, v + (th − 1)/2) is within ±radius of
    // (cx, cy), and whose template lies in the region.
    const int32_t uc = cx - (tw - 1) / 2, vc = cy - (th - 1) / 2;
    Search q{tpl, tw, th, region, NccSums{}, uc - radius, uc + radius, vc - radius, vc + radius};
    q.uc = uc;
    q.vc = vc;
    if (prior_q15 > 0)
        q.prior_scale = (int64_t{prior_q15} << 16) / (radius > 0 ? int64_t{radius} * radius : 1);
    if (q.u0 < region.x0) q.u0 = region.x0;
    if (q.v0 < region.y0) q.v0 = region.y0;
    if (q.u1 > region.x0 + region.w - tw) q.u1 = region.x0 + region.w - tw;
    if (q.v1 > region.y0 + region.h - th) q.v1 = region.y0 + region.h - th;
    // The template's Σa and Σa², summed once: each candidate then costs only Σb, Σb² and Σab
    // (3 multiply-adds a pixel instead of 5).
    q.t.n = uint32_t{tw} * th;
    for (uint32_t i = 0; i < q.t.n; ++i) {
        q.t.sa += tpl[i];
        q.t.saa += uint32_t{tpl[i]} * tpl[i];
    }
    if (q.u0 > q.u1 || q.v0 > q.v1) return hit;  // no candidate lies in the region
    Best best;
    const int32_t lattice = step < 1 ? 1 : step;
    // A template wider than half a strip (a few rows of many columns) is scored as it is.
    if (tw > kStrip / 2) {
        for (int32_t v = q.v0; v <= q.v1; ++v)
            for (int32_t u = q.u0; u <= q.u1; ++u) q.consider(u, v, best);
    } else if (lattice == 1 || int64_t{q.u1 - q.u0 + 1} * (q.v1 - q.v0 + 1) <= kExhaustiveUpTo) {
        scan_strips(q, 1, best);
    } else {
        coarse_to_fine(q, lattice, best);
    }
    hit.positions = best.positions;
    hit.found = true;
    hit.score_q15 = static_cast<int16_t>(best.ncc);
    int32_t dx = 0, dy = 0;
    subpixel_q8(q, best, &dx, &dy);
    hit.x_q8 = best.u * 256 + (tw - 1) * 128 + dx;
    hit.y_q8 = best.v * 256 + (th - 1) * 128 + dy;
    return hit;
}

}  // namespace qt

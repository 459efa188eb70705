#include "quads/quad_interior.h"

#include "base/floor_div.h"
#include "base/isqrt.h"

namespace qt {

namespace {

// q16.16 pixels to 1/16 pixel (floor): frames up to 2048 px give |values| < 2^15.
int32_t sixteenths(q16_16 v) { return v.raw >> 12; }

// A convex quadrangle's sides as half-planes (all in 1/16 px): p is inside side i by the margin
// when g_i(p) = dx[i]·(p.y − cy[i]) − dy[i]·(p.x − cx[i]) − need[i] >= 0 (> 0: by more), with
// need[i] = margin · |d_i| and d_i the side's direction times the orientation's sign, so that the
// inside is on the positive side of every one. A negative margin reaches outside. 32 × 32 →
// 64-bit products only (one SMULL each on a Cortex-M).
struct HalfPlanes {
    int32_t cx[4], cy[4], dx[4], dy[4];
    int64_t need[4];

    HalfPlanes(const Point16 corners[4], int32_t sign, int64_t margin16) {
        for (int i = 0; i < 4; ++i) {
            cx[i] = sixteenths(corners[i].x);
            cy[i] = sixteenths(corners[i].y);
        }
        for (int i = 0; i < 4; ++i) {
            const int j = (i + 1) & 3;
            dx[i] = sign * (cx[j] - cx[i]);
            dy[i] = sign * (cy[j] - cy[i]);
            const int64_t len2 =
                static_cast<int64_t>(dx[i]) * dx[i] + static_cast<int64_t>(dy[i]) * dy[i];
            need[i] = margin16 * static_cast<int64_t>(isqrt64(static_cast<uint64_t>(len2)));
        }
    }
    int64_t g(int s, int32_t x, int32_t y) const {
        return static_cast<int64_t>(dx[s]) * (y - cy[s]) -
               static_cast<int64_t>(dy[s]) * (x - cx[s]) - need[s];
    }
};

// Where half-plane s of h (g > 0) cuts pixel row y, kept from row to row without a division:
// g(16x, 16y) = A − 16·dy·x with A = g(0, 16y), so with D = 16·|dy| and
// q = ⌊(A − 1) / D⌋ the row's pixels inside are x <= q (dy > 0) or x >= −q (dy < 0), and all
// or none of them when dy = 0 (A > 0 or not). A grows by 16·dx a row: q and its remainder
// step by that over D (two divisions a side, not four a row).
class RowBound {
public:
    RowBound() = default;
    RowBound(const HalfPlanes& h, int s, int32_t y) {
        dy_ = h.dy[s];
        a_ = h.g(s, 0, 16 * y);
        step_a_ = 16 * static_cast<int64_t>(h.dx[s]);
        if (dy_ == 0) return;
        d_ = 16 * static_cast<int64_t>(dy_ < 0 ? -dy_ : dy_);
        q_ = floor_div(a_ - 1, d_);
        r_ = floor_mod(a_ - 1, d_);
        step_q_ = floor_div(step_a_, d_);
        step_r_ = floor_mod(step_a_, d_);
    }
    // Narrows [*lo, *hi] to this row's pixels inside the half-plane.
    void limit(int64_t* lo, int64_t* hi) const {
        if (dy_ > 0) {
            *hi = q_ < *hi ? q_ : *hi;
        } else if (dy_ < 0) {
            *lo = -q_ > *lo ? -q_ : *lo;
        } else if (a_ <= 0) {
            *hi = *lo - 1;
        }
    }
    void next_row() {
        a_ += step_a_;
        if (dy_ == 0) return;
        q_ += step_q_;
        r_ += step_r_;
        if (r_ >= d_) {
            r_ -= d_;
            ++q_;
        }
    }

private:
    int32_t dy_ = 0;
    int64_t a_ = 0, step_a_ = 0, d_ = 1, q_ = 0, r_ = 0, step_q_ = 0, step_r_ = 0;
};

}  // namespace

InteriorCount count_inside_edges(const EdgeList& edges, const Point16 corners[4], q16_16 margin) {
    InteriorCount count;
    // Twice the signed area (quad_rules.h, q16.16² raw: 2^32 a px²); its sign is the orientation.
    const int64_t area2 = shoelace2(corners);
    if (area2 == 0) return count;
    const int32_t sign = area2 < 0 ? -1 : 1;
    count.area_px = static_cast<uint32_t>((area2 < 0 ? -area2 : area2) >> 33);
    const HalfPlanes h(corners, sign, sixteenths(margin));
    const int32_t* cx = h.cx;
    const int32_t* cy = h.cy;
    int32_t x_lo = cx[0], x_hi = cx[0], y_lo = cy[0], y_hi = cy[0];
    for (int i = 1; i < 4; ++i) {
        x_lo = cx[i] < x_lo ? cx[i] : x_lo;
        x_hi = cx[i] > x_hi ? cx[i] : x_hi;
        y_lo = cy[i] < y_lo ? cy[i] : y_lo;
        y_hi = cy[i] > y_hi ? cy[i] : y_hi;
    }
    // Pixels whose centre is in the bounding box: ceil(lo / 16) .. floor(hi / 16); rows in
    // pairs, one row of cells each, its occupied cells as bits of x / 2.
    uint32_t occupied[(ep::kMaxCoordinate + 1) / 64] = {};
    const int32_t first_row = (y_lo + 15) >> 4, last_row = y_hi >> 4;
    const int32_t y0 = first_row < 0 ? 0 : first_row;
    RowBound bound[4];
    for (int s = 0; s < 4; ++s) bound[s] = RowBound(h, s, y0);
    for (int32_t y = y0; y <= last_row; ++y) {
        // The row's pixels inside every half-plane: one interval, from the four bounds.
        int64_t lo = (x_lo + 15) >> 4, hi = x_hi >> 4;
        for (RowBound& b : bound) {
            b.limit(&lo, &hi);
            b.next_row();
        }
        uint32_t i = 0, end = 0;
        if (lo <= hi) edges.span(static_cast<int32_t>(lo), static_cast<int32_t>(hi), y, &i, &end);
        for (; i < end; ++i) {
            const uint32_t cell = ep::x(edges[static_cast<uint16_t>(i)]) >> 1,
                           bit = 1u << (cell & 31u);
            count.cells += (occupied[cell >> 5] & bit) == 0;
            occupied[cell >> 5] |= bit;
        }
        if (y & 1)
            for (uint32_t& word : occupied) word = 0;
    }
    return count;
}

namespace {

// The share of segment a→b (1/16 px) lying in every half-plane of h (g >= 0), in 2^-20 of its
// length. |dx|, |dy|, |p − c| < 2^16 (frames up to 2048 px) and |need| < 2^24 (margins up to
// 16 px), so |g| < 2^33 and |g|·2^20 < 2^53.
int64_t share_inside20(const HalfPlanes& h, int32_t ax, int32_t ay, int32_t bx, int32_t by) {
    int64_t lo = 0, hi = int64_t{1} << 20;
    for (int s = 0; s < 4; ++s) {
        const int64_t ga = h.g(s, ax, ay), gb = h.g(s, bx, by);
        if (ga >= 0 && gb >= 0) continue;
        if (ga < 0 && gb < 0) return 0;
        if (ga < 0) {
            const int64_t t = (-ga * (int64_t{1} << 20)) / (gb - ga);  // enters here
            lo = t > lo ? t : lo;
        } else {
            const int64_t t = (ga * (int64_t{1} << 20)) / (ga - gb);  // leaves here
            hi = t < hi ? t : hi;
        }
    }
    return hi > lo ? hi - lo : 0;
}

}  // namespace

uint16_t count_lines_across(const Segment* lines, uint16_t n, const Point16 corners[4],
                            q16_16 margin, q16_16 min_inside) {
    const int64_t area2 = shoelace2(corners);
    if (area2 == 0) return 0;
    const int32_t sign = area2 < 0 ? -1 : 1;
    const int64_t margin16 = sixteenths(margin), min16 = sixteenths(min_inside);
    // By the margin inside every side, and by the margin outside.
    const HalfPlanes inner(corners, sign, margin16), outer(corners, sign, -margin16);
    uint16_t across = 0;
    for (uint16_t k = 0; k < n; ++k) {
        const int32_t ax = sixteenths(lines[k].x1), ay = sixteenths(lines[k].y1);
        const int32_t bx = sixteenths(lines[k].x2), by = sixteenths(lines[k].y2);
        const int64_t len16 = static_cast<int64_t>(
            isqrt64(static_cast<uint64_t>(static_cast<int64_t>(bx - ax) * (bx - ax) +
                                          static_cast<int64_t>(by - ay) * (by - ay))));
        if (len16 < min16) continue;
        if (((share_inside20(inner, ax, ay, bx, by) * len16) >> 20) < min16) continue;
        const int64_t near16 = (share_inside20(outer, ax, ay, bx, by) * len16) >> 20;
        if (len16 - near16 >= margin16) ++across;
    }
    return across;
}

bool interior_clear(const InteriorCount& count, uint16_t height, uint8_t limit_percent) {
    if (limit_percent == kCheckOff) return true;
    return static_cast<uint64_t>(count.cells) * 400u * isqrt32(uint32_t{height} << 16) <=
           static_cast<uint64_t>(limit_percent) * count.area_px * isqrt32(240u << 16);
}

}  // namespace qt

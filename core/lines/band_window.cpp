#include "lines/band_window.h"

#include "base/angle.h"
#include "base/floor_div.h"
#include "base/isqrt.h"

namespace qt {

namespace {

constexpr int32_t kSub = 16;  // 1/16 px

int32_t to_sub(q16_16 v) { return static_cast<int32_t>(floor_div(v.raw, 65536 / kSub)); }

}  // namespace

void BandWindow::set_quad(const q16_16 x[4], const q16_16 y[4], q16_16 half_width, q16_16 reach,
                          angle_t max_angle) {
    const int32_t hw = to_sub(half_width), ext = to_sub(reach);
    half_width_ = hw;
    fit_sides_ = false;
    for (int i = 0; i < 4; ++i) {
        corner_x_[i] = x[i];
        corner_y_[i] = y[i];
    }
    sin_max_q14_ = static_cast<int32_t>(sin_cos(max_angle).sin.raw >> 16);
    for (int b = 0; b < 4; ++b) {
        int32_t px[4], py[4];  // the band's rectangle, vertices in order, 1/16 px
        const int32_t ax = to_sub(x[b]), ay = to_sub(y[b]);
        const int32_t bx = to_sub(x[(b + 1) & 3]), by = to_sub(y[(b + 1) & 3]);
        const int64_t dx = bx - ax, dy = by - ay;
        const uint32_t len = isqrt64(static_cast<uint64_t>(dx * dx + dy * dy));
        // Unit vectors along the side (ux, uy) and across it (-uy, ux), Q14.
        const int64_t ux = len > 0 ? dx * 16384 / len : 16384, uy = len > 0 ? dy * 16384 / len : 0;
        const int32_t along_x = static_cast<int32_t>(ux * ext / 16384),
                      along_y = static_cast<int32_t>(uy * ext / 16384);
        const int32_t across_x = static_cast<int32_t>(-uy * hw / 16384),
                      across_y = static_cast<int32_t>(ux * hw / 16384);
        side_x_[b] = ax;
        side_y_[b] = ay;
        side_ux_[b] = static_cast<int32_t>(ux);
        side_uy_[b] = static_cast<int32_t>(uy);
        const int32_t sx = ax - along_x, sy = ay - along_y;  // the side's ends, extended
        const int32_t ex = bx + along_x, ey = by + along_y;
        // Rounding above moves a vertex by at most 1/16 px inwards: widen by that much.
        const int32_t wx = across_x + (across_x >= 0 ? 1 : -1),
                      wy = across_y + (across_y >= 0 ? 1 : -1);
        px[0] = sx + wx, py[0] = sy + wy;
        px[1] = ex + wx, py[1] = ey + wy;
        px[2] = ex - wx, py[2] = ey - wy;
        px[3] = sx - wx, py[3] = sy - wy;
        xmin_[b] = ymin_[b] = INT32_MAX;
        xmax_[b] = ymax_[b] = INT32_MIN;
        for (int v = 0; v < 4; ++v) {
            xmin_[b] = px[v] < xmin_[b] ? px[v] : xmin_[b];
            xmax_[b] = px[v] > xmax_[b] ? px[v] : xmax_[b];
            ymin_[b] = py[v] < ymin_[b] ? py[v] : ymin_[b];
            ymax_[b] = py[v] > ymax_[b] ? py[v] : ymax_[b];
        }
        along_row_[b] = uy == 0;
        const int64_t auy = uy < 0 ? -uy : uy;
        slope_q16_[b] = uy == 0 ? 0 : static_cast<int32_t>(ux * 65536 / uy);
        // Across a row the band is 2·hw/|uy| wide, plus the 1/16 px widening and a 1/16 px
        // for the rounding of the slope and of this quotient.
        half_x_[b] = uy == 0 ? 0 : static_cast<int32_t>((int64_t{hw} + 1) * 16384 / auy) + 2;
    }
    active_ = true;
}

uint8_t BandWindow::spans(int32_t first, int32_t last, int32_t grow, uint16_t width,
                          ColumnSpan out[kMaxSpans]) const {
    // The slab of the rows' squares, 1/16 px.
    const int32_t lo = first * kSub - kSub / 2, hi = last * kSub + kSub / 2;
    int32_t begin[4], end[4];
    uint8_t n = 0;
    for (int b = 0; b < 4; ++b) {
        if (hi < ymin_[b] || lo > ymax_[b]) continue;
        // The band's columns over the slab: the side's x at its two edges, widened by the
        // band's half extent across a row, within the rectangle's extent.
        int32_t xmin = xmin_[b], xmax = xmax_[b];
        if (!along_row_[b]) {
            const int32_t xa = side_x_[b] + static_cast<int32_t>(floor_div(
                                                int64_t{slope_q16_[b]} * (lo - side_y_[b]), 65536));
            const int32_t xb = side_x_[b] + static_cast<int32_t>(floor_div(
                                                int64_t{slope_q16_[b]} * (hi - side_y_[b]), 65536));
            const int32_t left = (xa < xb ? xa : xb) - half_x_[b],
                          right = (xa < xb ? xb : xa) + half_x_[b];
            xmin = left > xmin ? left : xmin;
            xmax = right < xmax ? right : xmax;
        }
        if (xmin > xmax) continue;
        // Pixel x's square [x - 1/2, x + 1/2] meets [xmin, xmax].
        const int64_t b0 = -floor_div(-(xmin - kSub / 2), kSub) - grow;  // ceil
        const int64_t b1 = floor_div(xmax + kSub / 2, kSub) + grow + 1;
        const int64_t c0 = b0 < 0 ? 0 : b0, c1 = b1 > width ? width : b1;
        if (c0 >= c1) continue;
        // Insert in order of begin.
        int32_t k = n++;
        for (; k > 0 && begin[k - 1] > c0; --k) {
            begin[k] = begin[k - 1];
            end[k] = end[k - 1];
        }
        begin[k] = static_cast<int32_t>(c0);
        end[k] = static_cast<int32_t>(c1);
    }
    uint8_t count = 0;
    for (uint8_t i = 0; i < n; ++i) {
        if (count > 0 && begin[i] <= out[count - 1].end) {
            if (end[i] > out[count - 1].end) out[count - 1].end = static_cast<uint16_t>(end[i]);
            continue;
        }
        out[count++] = ColumnSpan{static_cast<uint16_t>(begin[i]), static_cast<uint16_t>(end[i])};
    }
    return count;
}

void BandWindow::set_sides(const int8_t* bright_right) {
    fit_sides_ = bright_right != nullptr;
    for (int i = 0; i < 4; ++i) bright_right_[i] = fit_sides_ ? bright_right[i] : 0;
}

bool BandWindow::along_a_side(const Segment& line) const {
    const int32_t x1 = to_sub(line.x1), y1 = to_sub(line.y1);
    const int32_t x2 = to_sub(line.x2), y2 = to_sub(line.y2);
    const int64_t dx = x2 - x1, dy = y2 - y1;
    const int64_t len = isqrt64(static_cast<uint64_t>(dx * dx + dy * dy));
    const int64_t mx = (int64_t{x1} + x2) / 2, my = (int64_t{y1} + y2) / 2;
    for (int b = 0; b < 4; ++b) {
        // |u × d| <= sin(max_angle)·|d|, both sides Q14 · 1/16 px.
        const int64_t cross = side_ux_[b] * dy - side_uy_[b] * dx;
        if ((cross < 0 ? -cross : cross) > sin_max_q14_ * len) continue;
        // The midpoint's distance from the side's line, Q14 · 1/16 px.
        const int64_t off = side_ux_[b] * (my - side_y_[b]) - side_uy_[b] * (mx - side_x_[b]);
        if ((off < 0 ? -off : off) <= (int64_t{half_width_} + 2 * kSub) * 16384) return true;
    }
    return false;
}

void BandWindow::begin_frame(uint16_t width, uint16_t height) {
    width_ = width;
    height_ = height;
    for (Row& r : ring_) r.y = -1;
    grown_row_ = -1;
}

uint8_t BandWindow::row(int32_t y, const ColumnSpan** spans) {
    Row& r = ring_[y & 3];
    if (r.y != y) {
        r.y = y;
        r.n = y >= 0 && y < height_ ? this->spans(y, y, 0, width_, r.spans) : 0;
    }
    *spans = r.spans;
    return r.n;
}

uint8_t BandWindow::grown(int32_t r, const ColumnSpan** spans) {
    *spans = grown_;
    if (r == grown_row_) return grown_n_;  // asked twice: by the kernel and the edge stage
    grown_row_ = r;
    ColumnSpan* out = grown_;
    int32_t begin[kMaxGrown], end[kMaxGrown];
    uint8_t n = 0;
    for (int32_t y = r - 1; y <= r + 1; ++y) {
        const ColumnSpan* s = nullptr;
        const uint8_t count = row(y, &s);
        for (uint8_t i = 0; i < count; ++i) {
            const int32_t b = s[i].begin > 0 ? s[i].begin - 1 : 0;
            const int32_t e = s[i].end < width_ ? s[i].end + 1 : width_;
            int32_t k = n++;
            for (; k > 0 && begin[k - 1] > b; --k) {
                begin[k] = begin[k - 1];
                end[k] = end[k - 1];
            }
            begin[k] = b;
            end[k] = e;
        }
    }
    uint8_t count = 0;
    for (uint8_t i = 0; i < n; ++i) {
        if (count > 0 && begin[i] <= out[count - 1].end) {
            if (end[i] > out[count - 1].end) out[count - 1].end = static_cast<uint16_t>(end[i]);
            continue;
        }
        out[count++] = ColumnSpan{static_cast<uint16_t>(begin[i]), static_cast<uint16_t>(end[i])};
    }
    grown_n_ = count;
    return count;
}

}  // namespace qt

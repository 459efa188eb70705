// Tracking mode's window: bands around a tracked board's four sides, where the rows stage
// computes gradients and edges, and nowhere else.
//
// Why: once the board is tracked, each side of the next frame lies within a few pixels of its
// prediction, and the rest of the frame (its background, the board's own print) only costs
// work. A frame processed through a window gives, inside the bands, exactly the edges the full
// frame gives (an edge decision reads the 3 × 3 packed entries around it, each of which reads
// 3 × 3 pixels: both are computed wherever a band needs them); rows that no band crosses are
// skipped, and so are the columns of the others outside the bands.
//
// A band is the rectangle around side i (corner i to corner i + 1): the points within
// half_width px of the side's line, between its corners moved `reach` px outwards along it.
// Arithmetic in 1/16 px, integers only.
#pragma once
#include <stdint.h>

#include "base/fixed.h"
#include "lines/segment.h"

namespace qt {

// Columns [begin, end) of a row.
struct ColumnSpan {
    uint16_t begin, end;
};

class BandWindow {
public:
    static constexpr uint8_t kMaxSpans = 4;  // one per band; merged when they overlap

    // The bands around the quadrangle (x[i], y[i]) (px; side i from corner i to corner i + 1).
    // half_width, reach: px, 0..256. A side shorter than 1/16 px gives a square band.
    // max_angle: the lines along_a_side() keeps turn at most this far from their band's side.
    void set_quad(const q16_16 x[4], const q16_16 y[4], q16_16 half_width, q16_16 reach,
                  angle_t max_angle);

    // Side fitting (tracking mode): the quadrangle's corners as given to set_quad and each
    // side's contrast polarity, bright_right[i] +1 when the brighter side lies right of the
    // direction from corner i to corner i + 1 as seen (y down), -1 left, 0 unknown; with it,
    // the lines stage's caller measures each side by a fit to the edge points of its band
    // (BoardDetector) instead of PPHT and the quadrangle search. null: no side fitting.
    void set_sides(const int8_t* bright_right);
    bool fits_sides() const { return fit_sides_; }
    q16_16 corner_x(int i) const { return corner_x_[i]; }
    q16_16 corner_y(int i) const { return corner_y_[i]; }
    int8_t bright_right(int i) const { return bright_right_[i]; }
    q16_16 half_width() const { return q16_16::from_raw(int64_t{half_width_} * 4096); }

    // Whether the line runs along one of the sides: within max_angle of its direction, with
    // its midpoint within half_width (and 2 px) of the side's line. In a banded frame a line
    // that crosses a band is a background edge the band cuts short, not a side.
    bool along_a_side(const Segment& line) const;
    // No bands: the whole frame.
    void clear() { active_ = false; }
    bool active() const { return active_; }

    // The columns of rows first..last (inclusive) that a band reaches (a pixel is reached when
    // its square meets the band), each grown by `grow` px either way, clipped to [0, width):
    // merged and in increasing order into out[0 .. count). Returns count (0: no band there).
    uint8_t spans(int32_t first, int32_t last, int32_t grow, uint16_t width,
                  ColumnSpan out[kMaxSpans]) const;

    // The lines stage's view, a frame at a time: row(y) gives row y's spans (computed once a
    // frame: the edge decisions of row y read them), grown(r) the columns where packed
    // gradient row r must hold what the full row would (the spans of rows r − 1 .. r + 1 grown
    // by a pixel either way, where those decisions read it). Rows are asked for in increasing
    // order, at most three behind the newest.
    static constexpr uint8_t kMaxGrown = 3 * kMaxSpans;
    void begin_frame(uint16_t width, uint16_t height);
    uint8_t row(int32_t y, const ColumnSpan** spans);
    uint8_t grown(int32_t r, const ColumnSpan** spans);

private:
    // Band b row by row (set_quad divides once a frame, so that spans() only multiplies: a
    // division of 64-bit values is a library call on a Cortex-M): the side's x at y, x0 +
    // slope·(y − y0) (slope dx/dy in Q16), and the band's half extent across a row around it,
    // half_width / |uy| (1/16 px); none for a side along a row (uy = 0), whose band takes its
    // whole extent. The extents of its rectangle bound both.
    int32_t slope_q16_[4] = {}, half_x_[4] = {};
    bool along_row_[4] = {};
    int32_t xmin_[4] = {}, xmax_[4] = {};
    int32_t ymin_[4] = {}, ymax_[4] = {};  // band b's rows, 1/16 px
    // Side b's start (1/16 px) and unit direction (Q14); the bands' half width (1/16 px) and
    // sin(max_angle) (Q14).
    int32_t side_x_[4] = {}, side_y_[4] = {}, side_ux_[4] = {}, side_uy_[4] = {};
    int32_t half_width_ = 0, sin_max_q14_ = 0;
    q16_16 corner_x_[4] = {}, corner_y_[4] = {};
    int8_t bright_right_[4] = {};
    bool fit_sides_ = false;
    bool active_ = false;
    // The frame's rows: the last four rows' spans.
    struct Row {
        int32_t y = -1;
        uint8_t n = 0;
        ColumnSpan spans[kMaxSpans];
    };
    Row ring_[4];
    int32_t grown_row_ = -1;  // the row grown() gave last, and its spans
    uint8_t grown_n_ = 0;
    ColumnSpan grown_[kMaxGrown];
    uint16_t width_ = 0, height_ = 0;
};

}  // namespace qt

// The edge list: every edge pixel of a frame in raster order, packed in 32 bits, with an index
// of where each row starts, so that PPHT can both visit points in random order (by list index)
// and ask "is there an edge at (x, y)?" (binary search within one row) with no bitmap.
//
// When the list is full it keeps the strongest edges, and of the weaker ones every other step,
// never "the first ones in raster order". Each point also has its gradient magnitude (a byte
// beside it); a push onto a full list raises two levels so that at most 3/4 of the capacity
// stays, and removes the points that fall short (rows already filled included):
//   - thin_level(): the points at or above it, all of them, fill at most a quarter of that;
//   - below it, only the points on an even step of their edge's tangent axis stay
//     (ep::thinned_out): a long weak edge, a board's side against a bright wall, keeps every
//     other pixel, which PPHT (gaps up to max_line_gap) and the quadrangle evidence (a step
//     between two held ones counts) still follow, where a plain floor would lose all of it
//     to a background of shorter, stronger edges;
//   - floor(): below it, nothing.
// So the list always ends as "every edge of the frame at or above thin_level(), and every one
// on an even step at or above floor()", whatever the raster order (amortised cost: one
// compaction per capacity/4 pushes).
//
// Packed point, LSB first:
//   [10:0]  x      pixel column, 0..2047
//   [21:11] y      pixel row, 0..2047
//   [25:22] dir    gradient direction bin 0..15 (gradient_word.h), 22.5° each
//   [27:26] state  0 = not yet visited by PPHT, 1 = has voted, 2 = consumed by a segment
//   [31:28] delta  sub-pixel offset of the magnitude peak along the gradient axis, signed,
//                  1/16 of an axis step, -8..7 (the parabola through the NMS samples)
#pragma once
#include <stdint.h>

#include "base/status.h"

namespace qt {

using edge_point = uint32_t;

namespace ep {
constexpr uint32_t kMaxCoordinate = 2047;  // frames up to 2048 × 2048 pixels
constexpr uint32_t kFresh = 0, kVoted = 1, kConsumed = 2;
constexpr edge_point make(uint32_t x, uint32_t y, uint32_t dir, int32_t delta16 = 0) {
    return (x & 0x7FFu) | ((y & 0x7FFu) << 11) | ((dir & 15u) << 22) |
           ((static_cast<uint32_t>(delta16) & 15u) << 28);
}
constexpr uint32_t x(edge_point p) { return p & 0x7FFu; }
constexpr uint32_t y(edge_point p) { return (p >> 11) & 0x7FFu; }
constexpr uint32_t dir(edge_point p) { return (p >> 22) & 15u; }
constexpr uint32_t state(edge_point p) { return (p >> 26) & 3u; }
constexpr int32_t delta16(edge_point p) { return static_cast<int32_t>(((p >> 28) ^ 8u)) - 8; }
// Step of the gradient axis of direction bin d in 1/2 pixel: (2,0) for 0°, (2,1) for 22.5°
// (the odd axes interpolate between two neighbours), (2,2) for 45°, ...; negated for d >= 8.
constexpr int8_t kAxisX2[16] = {2, 2, 2, 1, 0, -1, -2, -2, -2, -2, -2, -1, 0, 1, 2, 2};
constexpr int8_t kAxisY2[16] = {0, 1, 2, 2, 2, 2, 2, 1, 0, -1, -2, -2, -2, -2, -2, -1};
constexpr int32_t axis_x2(uint32_t d) { return kAxisX2[d & 15u]; }
constexpr int32_t axis_y2(uint32_t d) { return kAxisY2[d & 15u]; }
// Sub-pixel position in 1/32 pixel: 32·(x, y) + delta16 · axis step (1/16 · 1/2).
constexpr int32_t x32(edge_point p) {
    return static_cast<int32_t>(x(p)) * 32 + delta16(p) * axis_x2(dir(p));
}
constexpr int32_t y32(edge_point p) {
    return static_cast<int32_t>(y(p)) * 32 + delta16(p) * axis_y2(dir(p));
}
// Thinning: true for a point on an odd step of its edge's tangent axis (y for a gradient
// direction nearer x, 45° and 135° included; x otherwise), the points a full list drops first
// below thin_level(): a thinned edge keeps every other step along itself.
constexpr bool thinned_out(edge_point p) {
    const uint32_t d = dir(p) & 7u;
    return (((d <= 2u || d >= 6u) ? y(p) : x(p)) & 1u) != 0;
}
constexpr edge_point with_state(edge_point p, uint32_t s) {
    return (p & ~(3u << 26)) | ((s & 3u) << 26);
}
}  // namespace ep

// Two neighbouring points of row y, remembered by EdgeList::find_near: point at − 1 at x =
// lo1 − 1 (lo1 = 0 when at is the row's first point) and point at at x = hi (hi = 2048 when
// at is past the row's last point); row y has no point between them.
struct RowProbe {
    uint16_t y = 0xFFFFu;  // no row (rows are below 2048)
    uint16_t lo1 = 0, hi = 0;
    uint16_t at = 0;
};

// Non-owning view of an edge list's storage; algorithms take this, so they are compiled once
// whatever the capacities. Fill it with begin_frame / begin_row / push, in raster order.
class EdgeList {
public:
    // strength: (capacity + 1) / 2 words, the points' magnitudes a byte each while the list
    // fills, then PPHT's working list (spare_words()).
    EdgeList(edge_point* points, uint16_t* strength, uint16_t capacity, uint16_t* row_start,
             uint16_t max_rows)
        : points_(points),
          strength_(reinterpret_cast<uint8_t*>(strength)),  // bytes of any object: defined
          spare_(strength),
          row_start_(row_start),
          capacity_(capacity),
          max_rows_(max_rows) {}

    // Empties the list for a frame of `height` rows; bad_size if height > max rows.
    Status begin_frame(uint16_t height);
    // Rows must be begun in increasing order, each once, before their points are pushed.
    void begin_row(uint16_t y);
    // Appends a point of the current row in increasing x; magnitude: its L1 gradient magnitude,
    // grey levels (0..510). A full list first drops its weakest points (see the top). Returns
    // false (and counts the point as dropped) when the point is below floor().
    bool push(uint16_t x, uint32_t dir, int32_t delta16, uint32_t magnitude);
    // Closes the frame: rows not begun are empty.
    void end_frame();

    uint16_t size() const { return count_; }
    uint16_t capacity() const { return capacity_; }
    uint32_t dropped() const { return dropped_; }  // points lost to the capacity this frame
    // Lowest magnitude kept this frame, grey levels (even; 0 until the list first filled):
    // every edge at or above it on an even step (and every one at or above thin_level()) is in
    // the list. An edge stage may skip weaker pixels.
    uint16_t floor() const { return floor_; }
    // Magnitude below which only points on an even step are kept, grey levels (even; 0 until
    // the list first filled).
    uint16_t thin_level() const { return thin_below_; }
    // The points' magnitudes matter only while the list fills and for hysteresis(): once the
    // frame is closed and filtered, their bytes are free, and PPHT keeps its working list there
    // (overwriting them): capacity() / 2 words.
    uint16_t* spare_words() { return spare_; }
    uint16_t height() const { return height_; }
    edge_point& operator[](uint16_t i) { return points_[i]; }
    edge_point operator[](uint16_t i) const { return points_[i]; }

    // Canny's hysteresis on a closed frame: keeps the points of magnitude >= high and every
    // point joined to one by a chain of 8-connected points of the list (all at or above the
    // low threshold the list was filled with), drops the rest (not counted in dropped(): a rule,
    // not a capacity). Scratch:
    // a stack of 2 bytes a point, scratch_bytes >= 2·size() (the Hough accumulator, unused
    // until PPHT, serves). Returns the points dropped; 0 and nothing done when the scratch is
    // too small. States are left 0 (fresh).
    uint32_t hysteresis(uint16_t high, uint8_t* scratch, uint32_t scratch_bytes);

    // Index of the point at (x, y), or -1 when there is none (or y is outside the frame).
    int32_t find(int32_t x, int32_t y) const;
    // The same answer, remembering in *probe the two points of row y about x, so that the
    // next search of that row nearby costs a compare or two: a walk along a row asks for x,
    // x ± 1, ... of the same few rows. A hit moves the probe on to the next pair of points the
    // way the walk goes; forward: the walk's way when the probe cannot answer (larger x when
    // true). A probe serves one filled list: RowProbe{} to begin with, and again after the
    // list changes. Inline: PPHT calls it for each row of its corridor at each step of a walk
    // along x.
    int32_t find_near(int32_t x, int32_t y, RowProbe& probe, bool forward) const {
        const uint32_t key = static_cast<uint32_t>(x);
        const uint32_t lo = probe.lo1 - 1u, hi = probe.hi;  // lo wraps to 2^32 − 1 for none
        if (probe.y != static_cast<uint32_t>(y) || key - lo > hi - lo)
            return search_and_probe(x, y, probe, forward);
        const uint32_t at = probe.at;
        if (key == hi) {
            if (hi > ep::kMaxCoordinate) return -1;
            // The pair after: this point and the next one.
            probe.lo1 = static_cast<uint16_t>(hi + 1u);
            probe.at = static_cast<uint16_t>(at + 1u);
            const bool next = at + 1u < row_start_[y + 1];
            probe.hi = static_cast<uint16_t>(next ? x_at(at + 1u) : ep::kMaxCoordinate + 1u);
            return static_cast<int32_t>(at);
        }
        if (key == lo && probe.lo1 != 0) {
            // The pair before: the point before this one and this one.
            probe.hi = static_cast<uint16_t>(lo);
            probe.at = static_cast<uint16_t>(at - 1u);
            probe.lo1 = static_cast<uint16_t>(at - 1u > row_start_[y] ? x_at(at - 2u) + 1u : 0u);
            return static_cast<int32_t>(at - 1u);
        }
        return -1;
    }
    // Row y's points with x_lo <= x <= x_hi: indices [*first, *end), empty when y is outside
    // the frame. One search for the span instead of one per pixel.
    void span(int32_t x_lo, int32_t x_hi, int32_t y, uint32_t* first, uint32_t* end) const;

private:
    uint32_t x_at(uint32_t i) const { return ep::x(points_[i]); }
    // find_near when the probe does not answer: a few steps from its point when it is of row
    // y, else a binary search; then the probe remembers what was found.
    int32_t search_and_probe(int32_t x, int32_t y, RowProbe& probe, bool forward) const;
    // Index of row y's first point with x >= key (row_start_[y + 1] when none); y in frame.
    uint32_t lower_bound(uint32_t key, uint32_t y) const;
    // Raises thin_below_ and floor_ until at most 3/4 of the capacity is left and removes the
    // points they no longer keep.
    void drop_weakest();

    edge_point* points_;
    uint8_t* strength_;    // magnitude / 2 (0..255) of each point
    uint16_t* spare_;      // the same storage as words
    uint16_t* row_start_;  // row_start_[y] .. row_start_[y + 1] - 1 are row y's points
    uint16_t capacity_;
    uint16_t max_rows_;
    uint16_t count_ = 0;
    uint16_t height_ = 0;
    uint16_t next_row_ = 0;  // rows below this have their start recorded
    uint16_t current_y_ = 0;
    uint16_t floor_ = 0;       // magnitude, grey levels
    uint16_t thin_below_ = 0;  // magnitude, grey levels: weaker points on an odd step go
    uint32_t dropped_ = 0;
};

// Storage for an edge list of Capacity points over frames of up to MaxRows rows:
// 5·Capacity (+ 1 when odd) + 2·(MaxRows + 1) bytes.
template <uint16_t Capacity, uint16_t MaxRows>
struct EdgeListStorage {
    static_assert(Capacity >= 4 && MaxRows >= 1, "room to drop a quarter");
    static_assert(MaxRows <= ep::kMaxCoordinate + 1, "rows fit the packed y");
    edge_point points[Capacity] = {};
    uint16_t strength[(Capacity + 1u) / 2u] = {};  // a byte a point (EdgeList's constructor)
    uint16_t row_start[MaxRows + 1] = {};
    EdgeList view() { return EdgeList(points, strength, Capacity, row_start, MaxRows); }
};

}  // namespace qt

// Edges from gradient words: L1 magnitude threshold plus non-maximum suppression along the
// quantised gradient direction, streaming over a three-row window. Works the same on words
// from core's GradientStage or from the FPGA block (the word is the interface).
//
// NMS: direction bins b and b + 8 share an axis. Even axes compare with the two neighbours
// along 0°, 45°, 90° or 135°; odd axes (22.5° between two of those) compare twice the
// magnitude with the sum of the two neighbours on each side (linear interpolation). A pixel is
// an edge when its magnitude >= edge_threshold, it is greater than the neighbour ahead (along
// +gradient) and not less than the one behind, so a plateau two pixels wide gives one edge.
// Pixels outside the frame count as magnitude 0.
//
// Input: rows of gradient words (push_row: the FPGA path) or rows already packed for NMS by
// NmsRowKernel straight from pixels (push_packed_row: the software path, which skips the
// gradient word and computes a direction only where the magnitude reaches the threshold —
// the only directions NMS reads — so both paths give the same edges).
//
// Memory: 4 rows of MaxWidth + 2 half-words (3 window rows and one zero row, one pad column
// each side): 8·(MaxWidth + 2) bytes (2576 B at 320).
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/status.h"
#include "gradient/gradient_word.h"
#include "lines/band_window.h"
#include "lines/edge_list.h"

namespace qt {

// One NMS entry: magnitude [8:0] and direction bin [12:9].
constexpr uint16_t nms_entry(uint32_t mag, uint32_t dir) {
    return static_cast<uint16_t>(mag | (dir << 9));
}

// One row of the NMS window: magnitude [8:0] and direction bin [12:9] of each pixel, with a
// zero at index 0 and at width + 1 so that x - 1 and x + 1 never leave the row.
void pack_nms_row(const gradient_word* words, uint16_t width, uint16_t* row);
// The same packed row straight from three pixel rows (gradient_row's geometry), with the
// direction left 0 where the magnitude is below edge_threshold.
void gradient_nms_row(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                      uint16_t width, uint16_t edge_threshold, uint16_t* row);
// The entries of columns [x_begin, x_end) only (x_end <= width), the pads and the other
// columns left as they were: what gradient_nms_row writes there.
void gradient_nms_span(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                       uint16_t width, uint16_t x_begin, uint16_t x_end, uint16_t edge_threshold,
                       uint16_t* row);

// GradientStage kernel producing packed NMS rows (kPad = 1: the pad columns). With a window
// (band_window.h), row y is computed only where NMS will read it: the columns the bands reach
// in rows y - 1 .. y + 1, grown by a pixel either way; a row no band comes near is not
// computed at all.
struct NmsRowKernel {
    using value_type = uint16_t;
    static constexpr uint16_t kPad = 1;
    uint16_t edge_threshold = 1;
    BandWindow* bands = nullptr;  // active bands (band_window.h), or null: the whole row
    void operator()(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                    uint16_t width, uint16_t y, uint16_t* out) const {
        if (bands == nullptr) {
            gradient_nms_row(above, center, below, width, edge_threshold, out);
            return;
        }
        out[0] = 0;
        out[width + 1] = 0;
        const ColumnSpan* spans = nullptr;
        const uint8_t n = bands->grown(y, &spans);
        for (uint8_t i = 0; i < n; ++i)
            gradient_nms_span(above, center, below, width, spans[i].begin, spans[i].end,
                              edge_threshold, out);
    }
};
// Appends row y's edges (centre row `c`, rows above `a` and below `b`, all packed) to `out`.
void nms_row(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t width, uint16_t y,
             uint16_t edge_threshold, EdgeList& out);
// The edges of columns [x_begin, x_end) of the row begun last in `out` (the rows' entries at
// x_begin - 1 .. x_end must hold what the full rows would): those nms_row appends there.
void nms_span(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t x_begin,
              uint16_t x_end, uint16_t edge_threshold, EdgeList& out);

template <uint16_t MaxWidth>
class EdgeStage {
public:
    // Starts a frame; edges go to `out` (emptied here). edge_threshold: L1 magnitude in grey
    // levels, 1..510. bad_size when a dimension is 0, width > MaxWidth or height exceeds the
    // list's rows.
    // bands: null, every pixel; else only the pixels of its active bands (band_window.h).
    Status begin_frame(uint16_t width, uint16_t height, uint16_t edge_threshold, EdgeList& out,
                       BandWindow* bands = nullptr) {
        in_frame_ = false;
        bands_ = bands;
        if (width == 0 || height == 0 || width > MaxWidth) return Status::bad_size;
        const Status s = out.begin_frame(height);
        if (s != Status::ok) return s;
        out_ = &out;
        width_ = width;
        height_ = height;
        threshold_ = edge_threshold;
        next_row_ = 0;
        in_frame_ = true;
        return Status::ok;
    }

    // Gradient words of the next row, in order. The list is complete (end_frame called) after
    // the last row.
    Status push_row(const gradient_word* words, uint16_t width) {
        const Status s = check_row(width);
        if (s != Status::ok) return s;
        pack_nms_row(words, width, rows_[next_row_ % 3]);
        advance();
        return Status::ok;
    }

    // A row packed by NmsRowKernel (width + 2 entries, pads included), in order.
    Status push_packed_row(const uint16_t* packed, uint16_t width) {
        const Status s = check_row(width);
        if (s != Status::ok) return s;
        uint16_t* slot = rows_[next_row_ % 3];
        if (bands_ == nullptr) {
            memcpy(slot, packed, (width + 2u) * sizeof(uint16_t));
        } else {  // what the window's decisions read: the row's pads and its grown spans
            slot[0] = 0;
            slot[width + 1] = 0;
            const ColumnSpan* spans = nullptr;
            const uint8_t n = bands_->grown(next_row_, &spans);
            for (uint8_t i = 0; i < n; ++i)
                memcpy(slot + spans[i].begin + 1, packed + spans[i].begin + 1,
                       (spans[i].end - spans[i].begin) * sizeof(uint16_t));
        }
        advance();
        return Status::ok;
    }

    bool in_frame() const { return in_frame_; }
    // The frame's edges came into the list from elsewhere (the FPGA's edge beats,
    // edge_beat.h): the stage takes no more rows of it.
    void close() { in_frame_ = false; }

private:
    Status check_row(uint16_t width) {
        if (!in_frame_) return Status::not_in_frame;
        if (width != width_) {
            in_frame_ = false;
            return Status::bad_row_length;
        }
        return Status::ok;
    }

    // The threshold of the next row's NMS: the list's floor once it is above ours (the list
    // would refuse the weaker edges; NMS decisions do not depend on the threshold, so this
    // gives the same list, with less work).
    uint16_t threshold() const { return out_->floor() > threshold_ ? out_->floor() : threshold_; }

    // Row next_row_ is in its slot: suppress the row before it (and the last row at the end).
    void advance() {
        const uint16_t y = next_row_;
        if (y >= 1) {
            const uint16_t* above = y >= 2 ? rows_[(y - 2) % 3] : zero_;
            decide(above, rows_[(y - 1) % 3], rows_[y % 3], static_cast<uint16_t>(y - 1));
        }
        if (y + 1u == height_) {
            const uint16_t* above = y >= 1 ? rows_[(y - 1) % 3] : zero_;
            decide(above, rows_[y % 3], zero_, y);
            out_->end_frame();
            in_frame_ = false;
        }
        next_row_ = static_cast<uint16_t>(y + 1u);
    }

    // Row y's edges: every pixel's, or those of the window's spans.
    void decide(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t y) {
        if (bands_ == nullptr) {
            nms_row(a, c, b, width_, y, threshold(), *out_);
            return;
        }
        const ColumnSpan* spans = nullptr;
        const uint8_t n = bands_->row(y, &spans);
        if (n == 0) return;
        out_->begin_row(y);
        for (uint8_t i = 0; i < n; ++i)
            nms_span(a, c, b, spans[i].begin, spans[i].end, threshold(), *out_);
    }

    uint16_t rows_[3][MaxWidth + 2] = {};
    uint16_t zero_[MaxWidth + 2] = {};
    EdgeList* out_ = nullptr;
    BandWindow* bands_ = nullptr;
    uint16_t width_ = 0, height_ = 0, threshold_ = 0, next_row_ = 0;
    bool in_frame_ = false;
};

}  // namespace qt

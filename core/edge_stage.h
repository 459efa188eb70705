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
// Memory: 4 rows of MaxWidth + 2 half-words (3 window rows and one zero row, one pad column
// each side): 8·(MaxWidth + 2) bytes (2576 B at 320).
#pragma once
#include <stdint.h>

#include "edge_list.h"
#include "gradient_word.h"
#include "status.h"

namespace qt {

// One row of the NMS window: magnitude [8:0] and direction bin [12:9] of each pixel, with a
// zero at index 0 and at width + 1 so that x - 1 and x + 1 never leave the row.
void pack_nms_row(const gradient_word* words, uint16_t width, uint16_t* row);
// Appends row y's edges (centre row `c`, rows above `a` and below `b`, all packed) to `out`.
void nms_row(const uint16_t* a, const uint16_t* c, const uint16_t* b, uint16_t width, uint16_t y,
             uint16_t edge_threshold, EdgeList& out);

template <uint16_t MaxWidth>
class EdgeStage {
public:
    // Starts a frame; edges go to `out` (emptied here). edge_threshold: L1 magnitude in grey
    // levels, 1..510. bad_size when a dimension is 0, width > MaxWidth or height exceeds the
    // list's rows.
    Status begin_frame(uint16_t width, uint16_t height, uint16_t edge_threshold, EdgeList& out) {
        in_frame_ = false;
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
        if (!in_frame_) return Status::not_in_frame;
        if (width != width_) {
            in_frame_ = false;
            return Status::bad_row_length;
        }
        const uint16_t y = next_row_;
        pack_nms_row(words, width, rows_[y % 3]);
        if (y >= 1) {
            const uint16_t* above = y >= 2 ? rows_[(y - 2) % 3] : zero_;
            nms_row(above, rows_[(y - 1) % 3], rows_[y % 3], width_, static_cast<uint16_t>(y - 1),
                    threshold_, *out_);
        }
        if (y + 1u == height_) {
            const uint16_t* above = y >= 1 ? rows_[(y - 1) % 3] : zero_;
            nms_row(above, rows_[y % 3], zero_, width_, y, threshold_, *out_);
            out_->end_frame();
            in_frame_ = false;
        }
        next_row_ = static_cast<uint16_t>(y + 1u);
        return Status::ok;
    }

    bool in_frame() const { return in_frame_; }

private:
    uint16_t rows_[3][MaxWidth + 2] = {};
    uint16_t zero_[MaxWidth + 2] = {};
    EdgeList* out_ = nullptr;
    uint16_t width_ = 0, height_ = 0, threshold_ = 0, next_row_ = 0;
    bool in_frame_ = false;
};

}  // namespace qt

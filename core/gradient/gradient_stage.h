// The streaming gradient stage: camera rows in, gradient rows out one row behind.
//
// Memory: two line buffers of MaxWidth bytes (rows y-1 and y; the incoming row is y+1) and
// one output row: 6·MaxWidth bytes with gradient words (3840 B at 640), no heap. Borders are
// replicated (docs/gradient.md). Output row y is handed to the sink when row y+1 arrives;
// the last row is handed over together with the second last when the final row arrives, so
// a frame of H rows makes exactly H sink calls.
//
// What a row becomes is the RowKernel's business: WordRowKernel (the default) makes gradient
// words, the FPGA block's output; XyWordRowKernel makes words with gx and gy only, for the
// Harris detector; edge_stage.h's NmsRowKernel makes the edge stage's packed rows directly,
// for the software path of the lines stage. A kernel is called as
// kernel(above, center, below, width, y, out) for row y.
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/status.h"
#include "gradient/gradient_word.h"

namespace qt {

// Gradient words of one row from the rows above, at and below it (w >= 1 pixels each).
void gradient_row(const uint8_t* above, const uint8_t* center, const uint8_t* below, uint16_t width,
                  gradient_word* out);

// Rows of gradient words, out[0 .. width).
struct WordRowKernel {
    using value_type = gradient_word;
    static constexpr uint16_t kPad = 0;  // extra entries before and after the row
    void operator()(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                    uint16_t width, uint16_t, gradient_word* out) const {
        gradient_row(above, center, below, width, out);
    }
};

// The same with gx and gy only (make_gradient_word_xy: magnitude and direction 0).
void gradient_row_xy(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                     uint16_t width, gradient_word* out);

// Rows of gx/gy-only words, out[0 .. width): what a Harris detector reads, and nothing else (on a
// Cortex-M4 the direction bin is most of a word's cost). The target pipeline's kernel is this one
// on the rows its detector reads only.
struct XyWordRowKernel {
    using value_type = gradient_word;
    static constexpr uint16_t kPad = 0;
    void operator()(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                    uint16_t width, uint16_t, gradient_word* out) const {
        gradient_row_xy(above, center, below, width, out);
    }
};

template <uint16_t MaxWidth, class RowKernel = WordRowKernel>
class GradientStage {
    static_assert(MaxWidth >= 1, "at least one pixel per row");
    using value_type = typename RowKernel::value_type;

public:
    RowKernel kernel;  // its parameters, if any, may change between rows

    static constexpr uint16_t kMaxWidth = MaxWidth;

    // Start a frame of width × height pixels. Returns bad_size (and no frame) when either is
    // 0 or width > MaxWidth; previous_frame_incomplete when a frame in progress was abandoned
    // (the new frame has started all the same).
    Status begin_frame(uint16_t width, uint16_t height) {
        const bool abandoned = in_frame_;
        in_frame_ = false;
        if (width == 0 || height == 0 || width > MaxWidth) return Status::bad_size;
        width_ = width;
        height_ = height;
        next_row_ = 0;
        in_frame_ = true;
        return abandoned ? Status::previous_frame_incomplete : Status::ok;
    }

    // Feed the next row (length pixels). On a wrong length the frame is abandoned and
    // bad_row_length returned; the next begin_frame() starts afresh. The sink is called as
    // sink(uint16_t y, const gradient_word* words, uint16_t width) for each finished row;
    // the words are valid only during the call.
    template <class Sink>
    Status push_row(const uint8_t* pixels, uint16_t length, Sink&& sink) {
        if (!in_frame_) return Status::not_in_frame;
        if (length != width_) {
            in_frame_ = false;
            return Status::bad_row_length;
        }
        const uint16_t y = next_row_;
        uint8_t* slot_y = rows_[y & 1u];             // where row y is kept
        const uint8_t* prev = rows_[(y + 1u) & 1u];  // row y-1 (row 0 while y <= 1)
        if (y >= 1) {
            // Row y-1 has all its neighbours now: above is row y-2 (in slot_y, about to be
            // overwritten) or row 0 replicated when y == 1.
            const uint8_t* above = y == 1 ? prev : slot_y;
            kernel(above, prev, pixels, width_, static_cast<uint16_t>(y - 1), out_);
            sink(static_cast<uint16_t>(y - 1), static_cast<const value_type*>(out_), width_);
        }
        memcpy(slot_y, pixels, width_);
        if (y + 1u == height_) {
            // Last row: its lower neighbour is itself (replicated border).
            kernel(y == 0 ? slot_y : prev, slot_y, slot_y, width_, y, out_);
            sink(y, static_cast<const value_type*>(out_), width_);
            in_frame_ = false;
        }
        next_row_ = static_cast<uint16_t>(y + 1u);
        return Status::ok;
    }

    bool in_frame() const { return in_frame_; }
    uint16_t width() const { return width_; }
    uint16_t height() const { return height_; }
    uint16_t rows_received() const { return next_row_; }

private:
    uint8_t rows_[2][MaxWidth] = {};
    value_type out_[MaxWidth + 2 * RowKernel::kPad] = {};
    uint16_t width_ = 0;
    uint16_t height_ = 0;
    uint16_t next_row_ = 0;
    bool in_frame_ = false;
};

}  // namespace qt

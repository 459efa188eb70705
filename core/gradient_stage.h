// The streaming gradient stage: camera rows in, gradient words out one row behind.
//
// Memory: two line buffers of MaxWidth bytes (rows y-1 and y; the incoming row is y+1) and
// one output row of MaxWidth words: 6·MaxWidth bytes in all (3840 B at 640), no heap.
// Borders are replicated (docs/gradient.md). Output row y is handed to the sink when row
// y+1 arrives; the last row is handed over together with the second last when the final
// row arrives, so a frame of H rows makes exactly H sink calls.
#pragma once
#include <stdint.h>
#include <string.h>

#include "gradient_word.h"
#include "status.h"

namespace qt {

// Gradient words of one row from the rows above, at and below it (w >= 1 pixels each).
void gradient_row(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                  uint16_t width, gradient_word* out);

template <uint16_t MaxWidth>
class GradientStage {
    static_assert(MaxWidth >= 1, "at least one pixel per row");

public:
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
        uint8_t* slot_y = rows_[y & 1u];          // where row y is kept
        const uint8_t* prev = rows_[(y + 1u) & 1u];  // row y-1 (row 0 while y <= 1)
        if (y >= 1) {
            // Row y-1 has all its neighbours now: above is row y-2 (in slot_y, about to be
            // overwritten) or row 0 replicated when y == 1.
            const uint8_t* above = y == 1 ? prev : slot_y;
            gradient_row(above, prev, pixels, width_, out_);
            sink(static_cast<uint16_t>(y - 1), static_cast<const gradient_word*>(out_), width_);
        }
        memcpy(slot_y, pixels, width_);
        if (y + 1u == height_) {
            // Last row: its lower neighbour is itself (replicated border).
            gradient_row(y == 0 ? slot_y : prev, slot_y, slot_y, width_, out_);
            sink(y, static_cast<const gradient_word*>(out_), width_);
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
    gradient_word out_[MaxWidth] = {};
    uint16_t width_ = 0;
    uint16_t height_ = 0;
    uint16_t next_row_ = 0;
    bool in_frame_ = false;
};

}  // namespace qt

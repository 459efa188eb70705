// Canny's Gaussian smoothing, streaming: camera rows in, rows smoothed by the binomial kernel
// [1 2 1]/4 ⊗ [1 2 1]/4 (a Gaussian of σ ≈ 0.7 px) out one row behind, replicated borders,
// rounded to nearest ((sum + 8) >> 4; exact integers, sum <= 16·255). The lines stage's Canny
// front end (LineParams::front_end) puts it before the gradient.
//
// Memory: two rows of MaxWidth bytes (rows y−1 and y while row y+1 arrives); the smoothed row
// y is written over row y−1 in place (one pixel of carry), handed to the sink, and then row
// y+1 takes that slot. No other buffer.
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/status.h"

namespace qt {

template <uint16_t MaxWidth>
class SmoothRows {
public:
    Status begin_frame(uint16_t width, uint16_t height) {
        in_frame_ = false;
        if (width == 0 || height == 0 || width > MaxWidth) return Status::bad_size;
        width_ = width;
        height_ = height;
        next_row_ = 0;
        in_frame_ = true;
        return Status::ok;
    }

    // Feeds the next row; sink(const uint8_t* smoothed, uint16_t width) is called for each
    // finished row, in order (H calls for H rows). bad_row_length abandons the frame.
    template <class Sink>
    Status push_row(const uint8_t* pixels, uint16_t length, Sink&& sink) {
        if (!in_frame_) return Status::not_in_frame;
        if (length != width_) {
            in_frame_ = false;
            return Status::bad_row_length;
        }
        const uint16_t y = next_row_;  // the incoming row
        uint8_t* slot_in = rows_[y & 1u];
        if (y == 1) {
            // Row 0: above is row 0 again. Its slot (1) is free: write there.
            smooth(rows_[0], rows_[0], pixels, rows_[1]);
            sink(static_cast<const uint8_t*>(rows_[1]), width_);
        } else if (y >= 2) {
            // Row y − 1 from rows y − 2 (in slot_in, written over), y − 1 and y.
            smooth(slot_in, rows_[(y - 1u) & 1u], pixels, slot_in);
            sink(static_cast<const uint8_t*>(slot_in), width_);
        }
        memcpy(slot_in, pixels, width_);
        if (y + 1u == height_) {
            // The last row: below is itself. Above is row y − 1 (or row 0 for a 1-row frame),
            // written over with the result.
            uint8_t* above = y == 0 ? rows_[1] : rows_[(y - 1u) & 1u];
            if (y == 0) memcpy(above, slot_in, width_);
            smooth(above, slot_in, slot_in, above);
            sink(static_cast<const uint8_t*>(above), width_);
            in_frame_ = false;
        }
        next_row_ = static_cast<uint16_t>(y + 1u);
        return Status::ok;
    }

    bool in_frame() const { return in_frame_; }

private:
    // out[x] = (h(a) + 2·h(b) + h(c) + 8) >> 4 with h = [1 2 1] along the row (replicated ends);
    // out may be a (each a[x] is read before out[x] is written; a[x − 1] is carried).
    void smooth(const uint8_t* a, const uint8_t* b, const uint8_t* c, uint8_t* out) const {
        const uint32_t w = width_;
        uint32_t a_left = a[0];
        for (uint32_t x = 0; x < w; ++x) {
            const uint32_t r = x + 1 < w ? x + 1 : x, l = x > 0 ? x - 1 : 0;
            const uint32_t ha = a_left + 2u * a[x] + a[r];
            const uint32_t hb = b[l] + 2u * b[x] + b[r];
            const uint32_t hc = c[l] + 2u * c[x] + c[r];
            a_left = a[x];
            out[x] = static_cast<uint8_t>((ha + 2u * hb + hc + 8u) >> 4);
        }
    }

    uint8_t rows_[2][MaxWidth] = {};
    uint16_t width_ = 0, height_ = 0, next_row_ = 0;
    bool in_frame_ = false;
};

}  // namespace qt

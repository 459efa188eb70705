// Integer binning: a camera frame larger than a stage's capacity reduced by a whole factor N in
// both directions, each output pixel the mean of an N × N block of input pixels — what a
// sensor's binning mode or an FPGA front end does. Rows in, binned rows out, no frame buffer:
// the stage in front of the gradient stage when the camera is larger than the build
// (1280 × 720 by 2 and 1920 × 1080 by 3 into a VGA build; docs/cli.md).
//
// Geometry. Output pixel (i, j) is the block of input pixels x in [N·i, N·i + N), y in
// [N·j, N·j + N). The output is floor(W / N) × floor(H / N) pixels: the last W mod N columns and
// H mod N rows, which make no whole block, are dropped (at most N − 1 px at the right and bottom
// edges). With pixel centres at integer coordinates (as everywhere in core/), output coordinate
// u is input coordinate N·u + (N − 1)/2: unbinned() maps results back.
//
// Arithmetic. A block's sum is exact in 16 bits (N² · 255 <= 65280 for N <= 16); the mean is
// (sum + ⌊N²/2⌋) / N² in integers: rounded to nearest, ties up. No float, no signed arithmetic.
//
// Memory: one row of MaxWidth 16-bit block sums (the N input rows of a block row accumulate
// there) and one output row of MaxWidth bytes: 3·MaxWidth bytes (1920 B at 640), no heap.
// Work: one addition per input pixel, one division per output pixel.
//
//   static qt::BinningStage<640> bin;
//   bin.begin_frame(1280, 720, 2);                       // or bin_factor_to_fit(1280, 720, ...)
//   for each camera row:
//       bin.push_row(row, 1280, [&](uint16_t y, const uint8_t* binned, uint16_t w) {
//           return det.push_row(binned, w);              // 640 × 360 rows into the detector
//       });
#pragma once
#include <stdint.h>

#include "base/fixed.h"
#include "base/setting_range.h"
#include "base/status.h"

namespace qt {

// The largest binning factor: 16 × 16 blocks still sum in 16 bits.
constexpr uint8_t kMaxBinFactor = 16;
// The binning factor's range (base/setting_range.h).
inline constexpr SettingRange kBinFactorRange{"", 1, kMaxBinFactor};

// The smallest factor N in 1..kMaxBinFactor for which floor(width / N) × floor(height / N) fits
// max_width × max_height (and is not empty); 0 when width or height is 0 or no factor fits.
constexpr uint8_t bin_factor_to_fit(uint16_t width, uint16_t height, uint16_t max_width,
                                    uint16_t max_height) {
    for (uint8_t n = 1; n <= kMaxBinFactor; ++n) {
        const uint16_t w = static_cast<uint16_t>(width / n), h = static_cast<uint16_t>(height / n);
        if (w == 0 || h == 0) return 0;
        if (w <= max_width && h <= max_height) return n;
    }
    return 0;
}

// A coordinate in binned pixels (q16_16) in the input frame's pixels: N·v + (N − 1)/2,
// saturated to q16_16's range. factor 1 returns v.
constexpr q16_16 unbinned(q16_16 v, uint8_t factor) {
    // |v.raw·N| < 2^31·16 and (N − 1)·2^15 < 2^19: no overflow in 64 bits.
    return q16_16::from_raw(static_cast<int64_t>(v.raw) * factor +
                            static_cast<int64_t>(factor - 1) * (q16_16::one_raw / 2));
}

template <uint16_t MaxWidth>
class BinningStage {
    static_assert(MaxWidth >= 1, "at least one output pixel per row");

public:
    static constexpr uint16_t kMaxWidth = MaxWidth;
    static constexpr uint32_t ram_bytes() { return sizeof(BinningStage); }

    // Starts a frame of width × height input pixels binned by `factor`. Returns bad_size (and
    // no frame) when width or height is 0, factor is 0 or above kMaxBinFactor, or the output
    // floor(width / factor) × floor(height / factor) would be empty or wider than MaxWidth;
    // previous_frame_incomplete when a frame in progress was abandoned (the new frame has
    // started all the same).
    Status begin_frame(uint16_t width, uint16_t height, uint8_t factor) {
        const bool abandoned = in_frame_;
        in_frame_ = false;
        if (width == 0 || height == 0 || factor == 0 || factor > kMaxBinFactor) {
            return Status::bad_size;
        }
        const uint16_t out_w = static_cast<uint16_t>(width / factor);
        const uint16_t out_h = static_cast<uint16_t>(height / factor);
        if (out_w == 0 || out_h == 0 || out_w > MaxWidth) return Status::bad_size;
        width_ = width;
        height_ = height;
        factor_ = factor;
        out_width_ = out_w;
        out_height_ = out_h;
        next_row_ = 0;
        for (uint16_t i = 0; i < out_w; ++i) sums_[i] = 0;
        in_frame_ = true;
        return abandoned ? Status::previous_frame_incomplete : Status::ok;
    }

    // Feeds the next input row of `length` pixels. After the last row of each block row (input
    // rows N·j + N − 1), calls sink(uint16_t j, const uint8_t* row, uint16_t out_width), which
    // returns a Status, with output row j (valid only during the call), and returns the sink's
    // status; otherwise ok. Rows past floor(height / N)·N are taken and dropped; after the
    // height-th row the frame is over (not_in_frame for any further row). On a wrong length the
    // frame is abandoned and bad_row_length returned; the next begin_frame() starts afresh.
    template <class Sink>
    Status push_row(const uint8_t* pixels, uint16_t length, Sink&& sink) {
        if (!in_frame_) return Status::not_in_frame;
        if (length != width_) {
            in_frame_ = false;
            return Status::bad_row_length;
        }
        const uint16_t y = next_row_;
        next_row_ = static_cast<uint16_t>(y + 1u);
        if (next_row_ == height_) in_frame_ = false;
        const uint16_t block_row = static_cast<uint16_t>(y / factor_);
        if (block_row >= out_height_) return Status::ok;  // the rows that make no whole block
        const uint8_t n = factor_;
        const uint8_t* p = pixels;
        for (uint16_t i = 0; i < out_width_; ++i) {
            uint32_t s = sums_[i];
            for (uint8_t k = 0; k < n; ++k) s += p[k];
            sums_[i] = static_cast<uint16_t>(s);  // <= N²·255 <= 65280
            p += n;
        }
        if (static_cast<uint16_t>(y % n) + 1 != n) return Status::ok;  // the block row goes on
        const uint32_t area = static_cast<uint32_t>(n) * n, half = area / 2u;
        for (uint16_t i = 0; i < out_width_; ++i) {
            out_[i] = static_cast<uint8_t>((sums_[i] + half) / area);
            sums_[i] = 0;
        }
        return sink(block_row, static_cast<const uint8_t*>(out_), out_width_);
    }

    bool in_frame() const { return in_frame_; }
    uint8_t factor() const { return factor_; }
    uint16_t width() const { return width_; }  // input, px
    uint16_t height() const { return height_; }
    uint16_t out_width() const { return out_width_; }  // output, px
    uint16_t out_height() const { return out_height_; }
    uint16_t rows_received() const { return next_row_; }

private:
    uint16_t sums_[MaxWidth] = {};
    uint8_t out_[MaxWidth] = {};
    uint16_t width_ = 0, height_ = 0, out_width_ = 0, out_height_ = 0, next_row_ = 0;
    uint8_t factor_ = 1;
    bool in_frame_ = false;
};

}  // namespace qt

// Template matching for the target tracker's measurement (the Filtering and Geometry paper Fig. 3):
// the target's template searched by zero-mean NCC (ncc_match.h) over the candidate centres of a
// search window, inside a region of the current frame captured while its rows streamed by. Integer
// only.
#pragma once
#include <stdint.h>
#include <string.h>

#include "base/floor_div.h"
#include "target/ncc_match.h"

namespace qt {

// The target's appearance: w × h grey levels (w, h <= MaxSide), centred on its pixel
// ((w − 1)/2, (h − 1)/2) — a half-pixel centre for an even side.
template <uint8_t MaxSide>
struct TargetTemplate {
    static_assert(MaxSide >= 3 && static_cast<uint32_t>(MaxSide) * MaxSide <= 1024,
                  "ncc_q15 takes blocks of at most 1024 pixels");
    uint8_t w = 0, h = 0;
    uint8_t pixels[MaxSide * MaxSide] = {};
};

// A rectangle of the current frame held in memory: pixel (x, y) of the frame, for x0 <= x <
// x0 + w and y0 <= y < y0 + h, is pixels[(y − y0)·stride + (x − x0)].
struct PixelRegion {
    const uint8_t* pixels = nullptr;
    uint32_t stride = 0;
    int32_t x0 = 0, y0 = 0;
    uint16_t w = 0, h = 0;
};

struct TemplateHit {
    bool found = false;  // at least one candidate centre had the whole template inside the region
    int32_t x_q8 = 0,
            y_q8 = 0;        // best template centre, 1/256 px (sub-pixel: one Newton step on the
                             // 3 × 3 NCC scores about the best, template_search.cpp)
    int16_t score_q15 = 0;   // its NCC, Q15
    uint32_t positions = 0;  // candidate centres scored
};

// Scores template placements whose centre lies within ±radius px (per axis) of (cx, cy) and
// whose pixels all lie in the region; keeps the best NCC (ties: the first in row-major order, so
// every platform agrees). With a motion prior (prior_q15 > 0) the best is that of the NCC less
// prior_q15·(d / radius)², d the placement's distance from the centre, as
// ⌊⌊prior_q15·2^16 / radius²⌋·d² / 2^16⌋ (Q15; radius 0 as 1): of two near-equal matches the
// nearer wins. score_q15 is the best's own NCC.
//   step 1: every placement. Work: positions · w · h multiply-adds (Σab; Σb and Σb² come from
//     column sums slid down the window: 2 per column and row of candidates), a root and a
//     division for each candidate that may beat the best so far.
//   step s > 1 (coarse to fine): every s-th placement along each axis from the window's
//     top-left, then every placement within ±(s − 1) of the three best of those: about 1/s² of
//     the work. It finds the window's best when that best's peak is wide enough for one of
//     the lattice's placements beside it to be among the three best; a peak narrower than s px
//     among distractors may be missed (the tests say how often on the benches' textures). A
//     window of at most 49 placements is searched whole.
// Then 8 more candidates scored in full for the sub-pixel step. A template of more than
// kNccMaxPixels pixels finds nothing.
TemplateHit search_template(const uint8_t* tpl, uint8_t tw, uint8_t th, const PixelRegion& region,
                            int32_t cx, int32_t cy, uint16_t radius, uint8_t step = 1,
                            int16_t prior_q15 = 0);

template <uint8_t MaxSide>
TemplateHit search_template(const TargetTemplate<MaxSide>& t, const PixelRegion& region, int32_t cx,
                            int32_t cy, uint16_t radius, uint8_t step = 1, int16_t prior_q15 = 0) {
    return search_template(t.pixels, t.w, t.h, region, cx, cy, radius, step, prior_q15);
}

// t moved 1/n of the way to c, rounded to nearest (halves up): t + round((c − t) / n); c
// itself at n <= 1. Always between t and c, so a pixel stays a pixel.
constexpr int32_t blend_toward(int32_t t, int32_t c, int32_t n) {
    return n <= 1 ? c
                  : t + static_cast<int32_t>(floor_div(2 * (int64_t{c} - t) + n, 2 * int64_t{n}));
}

// Copies a w × h template whose top-left pixel is (x, y) out of the region; false (template
// untouched) when it does not lie wholly inside or is larger than MaxSide.
template <uint8_t MaxSide>
bool cut_template(const PixelRegion& region, int32_t x, int32_t y, uint8_t w, uint8_t h,
                  TargetTemplate<MaxSide>& out) {
    if (w < 1 || h < 1 || w > MaxSide || h > MaxSide || x < region.x0 || y < region.y0 ||
        int64_t{x} + w > int64_t{region.x0} + region.w ||
        int64_t{y} + h > int64_t{region.y0} + region.h)
        return false;  // (64-bit sums: x, y may be anywhere in int32)
    out.w = w;
    out.h = h;
    for (uint8_t r = 0; r < h; ++r)
        memcpy(out.pixels + static_cast<uint32_t>(r) * w,
               region.pixels + static_cast<uint32_t>(y - region.y0 + r) * region.stride +
                   static_cast<uint32_t>(x - region.x0),
               w);
    return true;
}

// The template seen at a step f times coarser: out's pixel (X, Y) is the rounded mean of t's
// f × f pixels [f·X, f·X + f) × [f·Y, f·Y + f); out is ⌊w / f⌋ × ⌊h / f⌋ (t's last w mod f
// columns and h mod f rows left out). f <= 1: a copy.
template <uint8_t MaxSide>
void shrink_template(const TargetTemplate<MaxSide>& t, uint16_t f, TargetTemplate<MaxSide>& out) {
    if (f <= 1) {
        out = t;
        return;
    }
    out.w = static_cast<uint8_t>(t.w / f);
    out.h = static_cast<uint8_t>(t.h / f);
    const uint32_t area = static_cast<uint32_t>(f) * f;
    for (uint32_t y = 0; y < out.h; ++y)
        for (uint32_t x = 0; x < out.w; ++x) {
            uint32_t sum = 0;
            for (uint32_t j = 0; j < f; ++j)
                for (uint32_t i = 0; i < f; ++i) sum += t.pixels[(y * f + j) * t.w + x * f + i];
            out.pixels[y * out.w + x] = static_cast<uint8_t>((sum + area / 2) / area);
        }
}

// A rectangle of a streamed frame kept as its rows go by: at most MaxW × MaxH pixels. With a
// step s > 1 it keeps the frame shrunk by s: stored pixel (X, Y) is the rounded mean of the
// frame's s × s block [ox + s·X, ox + s·X + s) × [oy + s·Y, oy + s·Y + s), the grid's origin
// (ox, oy) in [0, s)² chosen per frame (a tracker puts it where the target's template starts,
// so that its blocks hold the same pixels as the template's did), and the region's coordinates
// are those block indices X, Y >= 0. A target of up to s·MaxTemplate px thus becomes a template
// of MaxTemplate. At the right and bottom edges a block is the mean of the pixels the frame has.
template <uint16_t MaxW, uint16_t MaxH>
class RegionCapture {
public:
    // s² · 255 must fit the uint16_t block sums.
    static constexpr uint16_t kMaxStep = 16;

    // Keeps [x0, x0 + w) × [y0, y0 + h) (in blocks of step × step frame pixels, 1..kMaxStep,
    // the grid from (ox, oy), each in [0, step)) clipped to the frame (and to MaxW × MaxH around
    // the requested box's centre). An empty intersection, or a step or origin out of range,
    // keeps nothing.
    // Arguments in 64 bits: the box may lie anywhere in int32 (TargetPipeline::set_target takes
    // any position), and its margins and far ends beyond.
    void begin(int64_t x0, int64_t y0, int64_t w, int64_t h, uint16_t frame_w, uint16_t frame_h,
               uint16_t step = 1, uint16_t ox = 0, uint16_t oy = 0) {
        int64_t left = x0, top = y0, width = w, height = h;
        if (width > MaxW) {
            left += (width - MaxW) / 2;
            width = MaxW;
        }
        if (height > MaxH) {
            top += (height - MaxH) / 2;
            height = MaxH;
        }
        int64_t right = left + width, bottom = top + height;
        const bool grid_ok =
            step >= 1 && step <= kMaxStep && ox < step && oy < step && ox < frame_w && oy < frame_h;
        const int64_t blocks_w = grid_ok ? (frame_w - ox + step - 1) / step : 0;
        const int64_t blocks_h = grid_ok ? (frame_h - oy + step - 1) / step : 0;
        if (left < 0) left = 0;
        if (top < 0) top = 0;
        if (right > blocks_w) right = blocks_w;
        if (bottom > blocks_h) bottom = blocks_h;
        if (right <= left || bottom <= top)
            left = top = right = bottom = 0;  // empty: keeps nothing
        region_.x0 = static_cast<int32_t>(left);
        region_.y0 = static_cast<int32_t>(top);
        region_.w = static_cast<uint16_t>(right - left);
        region_.h = static_cast<uint16_t>(bottom - top);
        region_.stride = MaxW;
        region_.pixels = pixels_;
        step_ = step;
        ox_ = ox;
        oy_ = oy;
        frame_w_ = frame_w;
        frame_h_ = frame_h;
        if (step_ > 1) memset(sums_, 0, sizeof sums_);
    }
    // Row y of the frame (pixels[0 .. frame width)), rows in order.
    void push_row(int32_t y, const uint8_t* row) {
        if (step_ <= 1) {
            if (y < region_.y0 || y >= region_.y0 + region_.h) return;
            memcpy(pixels_ + static_cast<uint32_t>(y - region_.y0) * MaxW, row + region_.x0,
                   region_.w);
            return;
        }
        const int32_t s = step_;
        if (region_.w == 0 || y < oy_) return;
        const int32_t block_row = (y - oy_) / s;
        if (block_row < region_.y0 || block_row >= region_.y0 + region_.h) return;
        // Frame column of block X's first pixel, and its columns: s, or fewer in a block cut by
        // the frame's right edge.
        auto first = [&](int32_t block) { return ox_ + block * s; };
        auto cols = [&](int32_t block) {
            const int32_t left = frame_w_ - first(block);
            return left < s ? left : s;
        };
        // The blocks in order, s pixels each, the last one fewer if the edge cuts it (only the
        // last can be cut: the region is clipped to the frame's blocks). Steps 2-4 unrolled: a
        // whole frame kept at a coarse step (the tracker's re-detection) passes every pixel
        // through here.
        const uint8_t* in = row + first(region_.x0);
        const int32_t whole = cols(region_.x0 + region_.w - 1) == s ? region_.w : region_.w - 1;
        switch (s) {
            case 2: add_blocks<2>(in, whole, s); break;
            case 3: add_blocks<3>(in, whole, s); break;
            case 4: add_blocks<4>(in, whole, s); break;
            default: add_blocks<0>(in, whole, s);
        }
        if (whole < region_.w) {
            uint32_t sum = sums_[whole];
            for (int32_t k = 0, n = cols(region_.x0 + whole); k < n; ++k) sum += in[whole * s + k];
            sums_[whole] = static_cast<uint16_t>(sum);
        }
        const int32_t rows = (y - oy_) % s + 1;    // of the block row so far
        if (rows < s && y + 1 < frame_h_) return;  // the block row goes on
        uint8_t* out = pixels_ + static_cast<uint32_t>(block_row - region_.y0) * MaxW;
        for (uint16_t i = 0; i < region_.w; ++i) {
            const uint32_t area = static_cast<uint32_t>(rows * cols(region_.x0 + i));
            out[i] = static_cast<uint8_t>((sums_[i] + area / 2) / area);
            sums_[i] = 0;
        }
    }
    const PixelRegion& region() const { return region_; }

private:
    // Adds the s pixels of each of the first n blocks of a row (from in) to their sums; S: s
    // when known at compile time (the loop unrolled), 0 otherwise.
    template <int32_t S>
    void add_blocks(const uint8_t* in, int32_t n, int32_t s) {
        const int32_t step = S > 0 ? S : s;
        for (int32_t i = 0; i < n; ++i, in += step) {
            uint32_t sum = sums_[i];
            for (int32_t k = 0; k < step; ++k) sum += in[k];
            sums_[i] = static_cast<uint16_t>(sum);
        }
    }

    uint8_t pixels_[static_cast<uint32_t>(MaxW) * MaxH] = {};
    uint16_t sums_[MaxW] = {};  // the block row in progress (step > 1)
    PixelRegion region_;
    uint16_t step_ = 1, ox_ = 0, oy_ = 0;
    int32_t frame_w_ = 0, frame_h_ = 0;
};

}  // namespace qt

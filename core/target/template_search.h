// Template matching for the target tracker's measurement (filtering-geometry.txt Fig. 3): the
// target's template searched by zero-mean NCC (ncc_match.h) over the candidate centres of a
// search window, inside a region of the current frame captured while its rows streamed by.
// Integer only.
#pragma once
#include <stdint.h>
#include <string.h>

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
            y_q8 = 0;        // best template centre, 1/256 px (parabolic sub-pixel fit on the NCC)
    int16_t score_q15 = 0;   // its NCC, Q15
    uint32_t positions = 0;  // candidate centres scored
};

// Scores every template placement whose centre lies within ±radius px (per axis) of
// (cx, cy) and whose pixels all lie in the region; keeps the best NCC (ties: the first in
// row-major order, so every platform agrees). Work: positions · w · h · 3 multiply-adds. A
// template of more than kNccMaxPixels pixels finds nothing.
TemplateHit search_template(const uint8_t* tpl, uint8_t tw, uint8_t th, const PixelRegion& region,
                            int32_t cx, int32_t cy, uint16_t radius);

template <uint8_t MaxSide>
TemplateHit search_template(const TargetTemplate<MaxSide>& t, const PixelRegion& region, int32_t cx,
                            int32_t cy, uint16_t radius) {
    return search_template(t.pixels, t.w, t.h, region, cx, cy, radius);
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

// A rectangle of a streamed frame kept as its rows go by: at most MaxW × MaxH pixels.
template <uint16_t MaxW, uint16_t MaxH>
class RegionCapture {
public:
    // Keeps [x0, x0 + w) × [y0, y0 + h) clipped to the frame (and to MaxW × MaxH around the
    // requested box's centre). An empty intersection keeps nothing.
    // Arguments in 64 bits: the box may lie anywhere in int32 (TargetPipeline::set_target takes
    // any position), and its margins and far ends beyond.
    void begin(int64_t x0, int64_t y0, int64_t w, int64_t h, uint16_t frame_w, uint16_t frame_h) {
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
        if (left < 0) left = 0;
        if (top < 0) top = 0;
        if (right > frame_w) right = frame_w;
        if (bottom > frame_h) bottom = frame_h;
        if (right <= left || bottom <= top)
            left = top = right = bottom = 0;  // empty: keeps nothing
        region_.x0 = static_cast<int32_t>(left);
        region_.y0 = static_cast<int32_t>(top);
        region_.w = static_cast<uint16_t>(right - left);
        region_.h = static_cast<uint16_t>(bottom - top);
        region_.stride = MaxW;
        region_.pixels = pixels_;
    }
    // Row y of the frame (pixels[0 .. frame width)).
    void push_row(int32_t y, const uint8_t* row) {
        if (y < region_.y0 || y >= region_.y0 + region_.h) return;
        memcpy(pixels_ + static_cast<uint32_t>(y - region_.y0) * MaxW, row + region_.x0, region_.w);
    }
    const PixelRegion& region() const { return region_; }

private:
    uint8_t pixels_[static_cast<uint32_t>(MaxW) * MaxH] = {};
    PixelRegion region_;
};

}  // namespace qt

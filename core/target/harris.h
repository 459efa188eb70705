// Harris corners from gradient words, streaming: the first step of the target tracker's
// homography estimate (the Filtering and Geometry paper, Table I, step 1). Works the same on words
// from core's GradientStage or from the FPGA block (the word is the interface).
//
// Per pixel, the structure tensor M = Σ [gx², gx·gy; gx·gy, gy²] over the (2·WindowRadius+1)²
// box centred on it (gx, gy: the word's central differences, grey levels), and the response
//   response = 25·det(M) − trace(M)²  (Harris with k = 1/25 = 0.04, scaled by 25; grey levels^4)
// exactly in integers. A corner is a pixel whose response
//   - is >= max(min_response, 1),
//   - is strictly greater than its 3×3 neighbours earlier in raster order (row above, left)
//     and >= those later (right, row below): a plateau gives one corner at its first pixel in
//     raster order unless it is concave from above (each raster-first pixel of it counts),
//   - lies at least kBorder = max(PatchRadius, WindowRadius + 1) px inside the frame, so that
//     its patch, its window and its neighbours' windows stay in the frame.
// Sub-pixel position: the vertex of the parabola through the responses at x−1, x, x+1 (and
// y−1, y, y+1), offset = (r₋ − r₊) / (2·(r₋ − 2r₀ + r₊)); r₀ > r₋ and r₀ >= r₊ make the
// denominator positive and |offset| <= 1/2 px, rounded half away from zero to 1/256 px.
// Bucketing: the frame is cut into grid_cols × grid_rows cells (cell of x: x·cols / width);
// each keeps its per_cell strongest corners (a stronger one replaces the weakest; order of
// strength: response, then earlier y, then earlier x). finish() writes them sorted by that
// order, strongest first.
// Bands (band_rows > 0): corners are sought only in the band of band_rows rows about the middle
// of each cell row; the gradient rows no band's windows reach (needs_gradient_row) are not read
// and cost nothing but the call. A band's corners are exactly the full frame's corners in its
// rows (each window sums the same rows). The target pipeline seeks corners in bands
// (target_pipeline.h): its homography needs a few well-spread corners a cell, not every corner.
//
// Row order: pixel rows 0..h−1 and gradient rows 0..h−1, each in order, with gradient row y
// pushed after pixel row y and before pixel row y+3 (GradientStage emits gradient row y while
// taking pixel row y+1, the last two together; the FPGA block is similar). Anything else
// returns bad_row_order and abandons the frame.
//
// Memory (no heap), bytes, W = MaxWidth, F = MaxFeatures, R = PatchRadius, V = WindowRadius:
//   gradient words of the last 2V+1 rows     4·(2V+1)·W     6400 at W 320, V 2
//   column sums of gx², gx·gy, gy²            12·W          3840
//   responses of the last 3 rows              24·W          7680
//   pixels of the last R+V+4 rows             (R+V+4)·W     3200 at R 4
//   kept corners with their patches           F·sizeof(Feature<R>)   96·104 = 9984
//   per-cell counts                           F             96
// sizeof(HarrisDetector<320, 96, 4, 2>) = 31 256 bytes on x86-64 and Cortex-M. The corners are
// sorted in place and read with features(): no second copy is needed for the frame.
#pragma once
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "base/setting_range.h"
#include "base/status.h"
#include "gradient/gradient_stage.h"
#include "gradient/gradient_word.h"
#include "target/feature.h"

namespace qt {

struct HarrisParams {
    // Floor on the response (units of Feature::response, grey levels^4); values below 1 act
    // as 1. Default 10^7: a right-angled step corner of contrast C peaks at 1319·C⁴ with the
    // 5×5 window (worked in tests/target/test_harris.cpp), so this keeps corners of contrast >= 10
    // grey levels; Gaussian noise of σ = 2 grey levels on a flat QVGA frame peaks at 5.7·10^6.
    int64_t min_response = 10000000;
    uint8_t grid_cols = 8, grid_rows = 6;  // bucketing grid over the frame, cells; >= 1 each
    uint8_t per_cell = 2;                  // strongest corners kept per cell, >= 1;
                                           // grid_cols·grid_rows·per_cell <= MaxFeatures
    // Rows of each cell row in which corners are sought: the band of this many rows about the
    // cell row's middle (0, or at least the cell row's height: every row). Gradient rows no
    // band's windows reach are not read.
    uint16_t band_rows = 0;
};

// HarrisParams' ranges (base/setting_range.h).
struct HarrisRanges {
    SettingRange band_rows{"rows", 0, 32767};
};
inline constexpr HarrisRanges kHarrisRanges{};

struct HarrisStats {
    uint32_t candidates = 0;  // corners found (maxima at or above the floor, inside the border)
    uint32_t replaced = 0;    // kept for a while, then replaced in their cell by a stronger one
    uint32_t dropped = 0;     // refused: their cell was full of stronger ones
    uint32_t weak = 0;        // 3×3 maxima with 0 < response < floor (not candidates)
    // Corners output = candidates − replaced − dropped.
};

template <uint16_t MaxWidth, uint16_t MaxFeatures, int PatchRadius = 4, int WindowRadius = 2>
class HarrisDetector {
    static_assert(MaxWidth >= 1 && MaxWidth <= 32767, "positions are int16_t");
    static_assert(MaxFeatures >= 1, "room for one corner at least");
    // Overflow: |gx|, |gy| <= 255, so each of Sxx, Syy, |Sxy| <= kS = (2V+1)²·255². det(M) =
    // Sxx·Syy − Sxy² ∈ [0, kS²] (Cauchy–Schwarz) and trace <= 2·kS, so every response lies in
    // [−4·kS², 21·kS²/4]; the sub-pixel step's denominator 2·r₀ − r₋ − r₊ is below 20·kS²,
    // bounds its numerator and is multiplied by 128: 20·128·kS² must fit.
    static_assert(WindowRadius >= 1 && WindowRadius <= 7, "windows of 3x3 .. 15x15 pixels");
    static constexpr int64_t kS = int64_t{2 * WindowRadius + 1} * (2 * WindowRadius + 1) * 65025;
    static_assert(25 * kS < (int64_t{1} << 31), "sums, and 25·Sxx for the response, fit int32");
    static_assert(kS * kS < INT64_MAX / 2560, "responses and the sub-pixel step fit int64");

public:
    static constexpr int kWindowRows = 2 * WindowRadius + 1;
    static constexpr int kPixelRows = PatchRadius + WindowRadius + 4;  // see push_pixel_row
    static constexpr int kBorder = PatchRadius > WindowRadius + 1 ? PatchRadius : WindowRadius + 1;
    static constexpr uint16_t kMaxHeight = 32767;  // positions are int16_t

    // Starts a frame of width × height pixels. bad_size (and no frame) when a dimension is 0,
    // width > MaxWidth, height > kMaxHeight, a grid dimension or per_cell is 0, or
    // grid_cols·grid_rows·per_cell > MaxFeatures (refused, not clamped: the caller chose the
    // spread). previous_frame_incomplete when a frame in progress was abandoned (the new
    // frame has started all the same).
    Status begin_frame(uint16_t width, uint16_t height, const HarrisParams& config) {
        const bool abandoned = in_frame_;
        in_frame_ = false;
        if (width == 0 || height == 0 || width > MaxWidth || height > kMaxHeight)
            return Status::bad_size;
        const uint32_t slots = uint32_t{config.grid_cols} * config.grid_rows * config.per_cell;
        if (slots == 0 || slots > MaxFeatures) return Status::bad_size;
        config_ = config;
        if (config_.min_response < 1) config_.min_response = 1;
        width_ = width;
        height_ = height;
        pixel_rows_ = 0;
        gradient_rows_ = 0;
        filled_ = 0;
        stats_ = HarrisStats{};
        memset(cell_count_, 0, sizeof cell_count_);
        in_frame_ = true;
        return abandoned ? Status::previous_frame_incomplete : Status::ok;
    }

    // Pixel row `pixel_rows_received()`, length = width. Kept for the patches: the ring holds
    // R+V+4 rows, enough for a corner of row r found when gradient row r+V+1 arrives (pixel
    // rows up to r+V+3 may be in by then, rows from r−R are needed); patch rows arriving after
    // the corner is found are copied as they come.
    Status push_pixel_row(const uint8_t* pixels, uint16_t length) {
        if (!in_frame_ || pixel_rows_ == height_) return Status::not_in_frame;
        if (length != width_) return abandon(Status::bad_row_length);
        const uint16_t y = pixel_rows_;
        if (y >= gradient_rows_ + 3) return abandon(Status::bad_row_order);
        memcpy(pixels_[y % kPixelRows], pixels, row_width());
        pixel_rows_ = static_cast<uint16_t>(y + 1u);
        // A corner of cell row j lies in j's rows: only the cell rows within PatchRadius rows
        // of y can have a patch row here.
        const int g = config_.grid_rows, h = height_;
        const int lo = y < PatchRadius ? 0 : y - PatchRadius;
        const int hi = y + PatchRadius >= h ? h - 1 : y + PatchRadius;
        const uint32_t first = static_cast<uint32_t>(lo * g / h) * config_.grid_cols;
        const uint32_t end = static_cast<uint32_t>(hi * g / h + 1) * config_.grid_cols;
        for (uint32_t c = first; c < end; ++c)
            for (uint32_t k = 0; k < cell_count_[c]; ++k) {
                Feature<PatchRadius>& f = kept_.items[c * config_.per_cell + k];
                const int dy = y - f.py;
                if (dy >= -PatchRadius && dy <= PatchRadius) copy_patch_row(f, dy);
            }
        return Status::ok;
    }

    // Gradient row y (y = gradient_rows_received(), length = width words). Out of line: inlined
    // into a large caller (the firmware's frame loop), its per-pixel loops lose their registers
    // to the caller's values (rows 6.6 M → 7.5 M Cortex-M4F instructions a frame).
    __attribute__((noinline)) Status push_gradient_row(uint16_t y, const gradient_word* words,
                                                       uint16_t length) {
        if (!in_frame_ || gradient_rows_ == height_) return Status::not_in_frame;
        if (length != width_) return abandon(Status::bad_row_length);
        if (y != gradient_rows_ || y >= pixel_rows_) return abandon(Status::bad_row_order);
        gradient_rows_ = static_cast<uint16_t>(y + 1u);
        if (width_ < kWindowRows) return Status::ok;  // no window fits: no responses
        // A row no band needs breaks the run of rows in the column sums; the next needed row
        // starts a new one.
        if (!needs_gradient_row(y)) {
            filled_ = 0;
            return Status::ok;
        }
        gradient_word* slot = grads_[y % kWindowRows];
        const int yc = y - WindowRadius;  // the row whose windows are complete after this one
        if (filled_ == 0) {
            memset(col_xx_, 0, sizeof col_xx_);
            memset(col_xy_, 0, sizeof col_xy_);
            memset(col_yy_, 0, sizeof col_yy_);
        }
        // Row y enters the window; row y − (2V+1), in the slot it takes, leaves it.
        if (filled_ >= kWindowRows) {
            slide_and_respond(slot, words, resp_[yc % 3]);
        } else {
            add_row(words);
            if (filled_ + 1 == kWindowRows) response_row(resp_[yc % 3]);  // the first windows
        }
        memcpy(slot, words, row_width() * sizeof(gradient_word));
        if (filled_ < kWindowRows + 2) ++filled_;
        // Row r = yc − 1 has its responses and those of its neighbours once 2V+3 rows are in.
        const int r = yc - 1;
        if (filled_ == kWindowRows + 2 && r >= kBorder && r <= height_ - 1 - kBorder && in_band(r))
            suppress_row(r);
        return Status::ok;
    }

    // After every row: the kept corners, strongest first, in features() (count <= MaxFeatures),
    // sorted in place. not_in_frame (count 0) when no frame is in progress or rows are missing;
    // the frame ends either way.
    Status finish() {
        kept_.width = width_;
        kept_.height = height_;
        const bool complete = in_frame_ && pixel_rows_ == height_ && gradient_rows_ == height_;
        in_frame_ = false;
        kept_.count = 0;
        if (!complete) return Status::not_in_frame;
        // The used slots packed to the front (a slot's index is never below its new one) ...
        uint16_t n = 0;
        const uint32_t cells = uint32_t{config_.grid_cols} * config_.grid_rows;
        for (uint32_t c = 0; c < cells; ++c)
            for (uint32_t k = 0; k < cell_count_[c]; ++k, ++n) {
                const uint32_t slot = c * config_.per_cell + k;
                if (slot != n) kept_.items[n] = kept_.items[slot];
            }
        // ... an insertion sort of their indices by strength ...
        uint16_t order[MaxFeatures];
        for (uint16_t k = 0; k < n; ++k) {
            uint16_t i = k;
            for (; i > 0 && stronger(kept_.items[k], kept_.items[order[i - 1]]); --i)
                order[i] = order[i - 1];
            order[i] = k;
        }
        // ... then items[i] = old items[order[i]] in place, cycle by cycle, one corner of
        // scratch (order[i] = MaxFeatures marks a placed entry).
        for (uint16_t i = 0; i < n; ++i) {
            if (order[i] == MaxFeatures || order[i] == i) continue;
            const Feature<PatchRadius> first = kept_.items[i];
            uint16_t at = i;
            while (order[at] != i) {
                const uint16_t from = order[at];
                kept_.items[at] = kept_.items[from];
                order[at] = MaxFeatures;
                at = from;
            }
            kept_.items[at] = first;
            order[at] = MaxFeatures;
        }
        kept_.count = n;
        return Status::ok;
    }

    // The same, copied into `out`.
    Status finish(FeatureSet<PatchRadius, MaxFeatures>& out) {
        const Status s = finish();
        out.width = kept_.width;
        out.height = kept_.height;
        out.count = kept_.count;
        for (uint16_t i = 0; i < kept_.count; ++i) out.items[i] = kept_.items[i];
        return s;
    }

    // The last finished frame's corners (valid until the next begin_frame()).
    const FeatureSet<PatchRadius, MaxFeatures>& features() const { return kept_; }

    const HarrisStats& stats() const { return stats_; }
    bool in_frame() const { return in_frame_; }
    uint16_t pixel_rows_received() const { return pixel_rows_; }
    uint16_t gradient_rows_received() const { return gradient_rows_; }

    // Whether the frame's gradient row y is read: it reaches the windows of a band's row or of
    // its neighbours above and below (suppression reads them). The words of a row that is not
    // read may be anything (the target pipeline does not compute them).
    bool needs_gradient_row(int y) const {
        if (config_.band_rows == 0) return true;
        constexpr int kReach = WindowRadius + 1;
        const int g = config_.grid_rows, h = height_;
        const int lo = y - kReach < 0 ? 0 : y - kReach, hi = y + kReach >= h ? h - 1 : y + kReach;
        for (int j = lo * g / h; j <= hi * g / h; ++j) {
            const Band b = band(j);
            if (y >= b.first - kReach && y < b.end + kReach) return true;
        }
        return false;
    }

    // The strength order of finish(): response, then smaller y, then smaller x.
    static bool stronger(const Feature<PatchRadius>& a, const Feature<PatchRadius>& b) {
        if (a.response != b.response) return a.response > b.response;
        if (a.py != b.py) return a.py < b.py;
        return a.px < b.px;
    }

private:
    // width_, which begin_frame() keeps <= MaxWidth; the bound written out lets a compiler see
    // that row copies stay in their rows (aarch64 GCC 12 warns otherwise).
    size_t row_width() const { return width_ < MaxWidth ? width_ : MaxWidth; }

    Status abandon(Status s) {
        in_frame_ = false;
        return s;
    }

    // The rows [first, end) of cell row j's band (HarrisParams::band_rows): cell row j holds
    // rows [ceil(j·h/g), ceil((j+1)·h/g)), the rows whose cell row is j (y·g/h).
    struct Band {
        int first, end;
    };
    Band band(int j) const {
        const int g = config_.grid_rows, h = height_;
        const int start = (j * h + g - 1) / g, stop = ((j + 1) * h + g - 1) / g;
        if (config_.band_rows == 0 || config_.band_rows >= stop - start) return Band{start, stop};
        const int first = start + (stop - start - config_.band_rows) / 2;
        return Band{first, first + config_.band_rows};
    }
    bool in_band(int r) const {
        const Band b = band(r * config_.grid_rows / height_);
        return r >= b.first && r < b.end;
    }

    // Adds a gradient row's products to the column sums. Each column sum holds at most 2V+1
    // products of <= 65025: below kS < 2^31.
    void add_row(const gradient_word* row) {
        for (uint16_t x = 0; x < width_; ++x) {
            const int32_t gx = gradient_gx(row[x]), gy = gradient_gy(row[x]);
            col_xx_[x] += gx * gx;
            col_xy_[x] += gx * gy;
            col_yy_[x] += gy * gy;
        }
    }
    // 25·det(M) − trace(M)² of the window sums, as (25·Sxx)·Syy + (−5·Sxy)·(5·Sxy) +
    // (−trace)·trace: every factor fits 32 bits (25·kS < 2^31), so one 32 × 32 → 64-bit product
    // and two that add to it (SMULL, SMLAL, SMLAL on a Cortex-M4), and the same integer.
    static int64_t response_of(int32_t sxx, int32_t sxy, int32_t syy) {
        const int32_t s5 = 5 * sxy, trace = sxx + syy;
        int64_t response = int64_t{25 * sxx} * syy;
        response += int64_t{-s5} * s5;
        response += int64_t{-trace} * trace;
        return response;
    }

    // Responses of the row whose windows the column sums now cover, for x in [V, w−1−V]
    // (the only ones suppress_row reads), by a sliding sum over the columns.
    void response_row(int64_t* out) const {
        constexpr int V = WindowRadius;
        int32_t sxx = 0, sxy = 0, syy = 0;
        for (int x = 0; x < kWindowRows - 1; ++x) {
            sxx += col_xx_[x];
            sxy += col_xy_[x];
            syy += col_yy_[x];
        }
        for (int x = V; x + V < width_; ++x) {
            sxx += col_xx_[x + V];
            sxy += col_xy_[x + V];
            syy += col_yy_[x + V];
            out[x] = response_of(sxx, sxy, syy);
            sxx -= col_xx_[x - V];
            sxy -= col_xy_[x - V];
            syy -= col_yy_[x - V];
        }
    }

    // Adds row `in`'s products to the column sums and removes row `out`'s, and writes the
    // responses of the row whose windows the sums then cover (width_ >= 2V+1), in one pass over
    // the columns: a column's new sums go into the window's from registers instead of being
    // stored and read back (the rows stage of the Cortex-M4F target image). The difference of
    // two products lies in ±65025 and the sums before and after are those of 2V+1 rows: no
    // overflow.
    void slide_and_respond(const gradient_word* out_row, const gradient_word* in_row,
                           int64_t* out) {
        constexpr int V = WindowRadius, D = 2 * WindowRadius;
        int32_t sxx = 0, sxy = 0, syy = 0;
        for (int x = 0; x < width_; ++x) {
            const int32_t ox = gradient_gx(out_row[x]), oy = gradient_gy(out_row[x]);
            const int32_t ix = gradient_gx(in_row[x]), iy = gradient_gy(in_row[x]);
            const int32_t cxx = col_xx_[x] + (ix * ix - ox * ox);
            const int32_t cxy = col_xy_[x] + (ix * iy - ox * oy);
            const int32_t cyy = col_yy_[x] + (iy * iy - oy * oy);
            col_xx_[x] = cxx;
            col_xy_[x] = cxy;
            col_yy_[x] = cyy;
            sxx += cxx;
            sxy += cxy;
            syy += cyy;
            if (x < D) continue;  // the first window is not complete yet
            out[x - V] = response_of(sxx, sxy, syy);
            sxx -= col_xx_[x - D];
            sxy -= col_xy_[x - D];
            syy -= col_yy_[x - D];
        }
    }

    // round(128·num / den), half away from zero; den > 0, |num| <= den (so |result| <= 128).
    static int32_t half_pixel_q8(int64_t num, int64_t den) {
        const int64_t n = 128 * (num < 0 ? -num : num);
        const int64_t q = (n + den / 2) / den;
        return static_cast<int32_t>(num < 0 ? -q : q);
    }

    // Non-maximum suppression of row r (kBorder <= r <= h−1−kBorder), whose responses and
    // those of rows r±1 are in the ring.
    void suppress_row(int r) {
        const int64_t* up = resp_[(r - 1) % 3];
        const int64_t* mid = resp_[r % 3];
        const int64_t* down = resp_[(r + 1) % 3];
        // Along the row first: x is a maximum only when mid[x − 1] < v >= mid[x + 1], and then
        // x + 1 is not (its left neighbour, x, is not below it), so a step of two. The box
        // sums make the responses smooth: most pixels fail against a neighbour in the row,
        // one or two compares each instead of eight. The same maxima, found in the same order.
        const int last = width_ - 1 - kBorder;  // mid[last + 1] is a response too (kBorder > V)
        for (int x = kBorder; x <= last; ++x) {
            const int64_t v = mid[x];
            if (v <= 0 || v < mid[x + 1]) continue;
            const bool maximum = v > mid[x - 1] && v > up[x - 1] && v > up[x] && v > up[x + 1] &&
                                 v >= down[x - 1] && v >= down[x] && v >= down[x + 1];
            const int at = x++;  // x + 1 is no maximum (v >= mid[x + 1])
            if (!maximum) continue;
            if (v < config_.min_response) {
                ++stats_.weak;
                continue;
            }
            ++stats_.candidates;
            Feature<PatchRadius> f;
            f.px = static_cast<int16_t>(at);
            f.py = static_cast<int16_t>(r);
            f.response = v;
            // Denominators 2v − r₋ − r₊ >= v − r₋ > 0 and >= |r₋ − r₊| (v >= r₊).
            f.x_q8 = at * 256 +
                     half_pixel_q8(mid[at + 1] - mid[at - 1], 2 * v - mid[at - 1] - mid[at + 1]);
            f.y_q8 = r * 256 + half_pixel_q8(down[at] - up[at], 2 * v - up[at] - down[at]);
            keep(f);
        }
    }

    // Bucketing: into the corner's cell, or over its weakest, or dropped.
    void keep(const Feature<PatchRadius>& f) {
        const uint32_t cx = static_cast<uint32_t>(f.px) * config_.grid_cols / width_;
        const uint32_t cy = static_cast<uint32_t>(f.py) * config_.grid_rows / height_;
        const uint32_t cell = cy * config_.grid_cols + cx;
        Feature<PatchRadius>* slots = kept_.items + cell * config_.per_cell;
        uint8_t& count = cell_count_[cell];
        Feature<PatchRadius>* target;
        if (count < config_.per_cell) {
            target = slots + count++;
        } else {
            target = slots;
            for (uint32_t k = 1; k < count; ++k)
                if (stronger(*target, slots[k])) target = slots + k;
            if (!stronger(f, *target)) {
                ++stats_.dropped;
                return;
            }
            ++stats_.replaced;
        }
        *target = f;
        // The patch rows already in the ring (rows from r − R: see push_pixel_row); the others
        // come with their pixel rows.
        for (int dy = -PatchRadius; dy <= PatchRadius && f.py + dy < pixel_rows_; ++dy)
            copy_patch_row(*target, dy);
    }

    void copy_patch_row(Feature<PatchRadius>& f, int dy) {
        const uint8_t* src = pixels_[(f.py + dy) % kPixelRows] + (f.px - PatchRadius);
        memcpy(f.patch + (dy + PatchRadius) * Feature<PatchRadius>::kSide, src,
               Feature<PatchRadius>::kSide);
    }

    gradient_word grads_[static_cast<unsigned>(kWindowRows)][MaxWidth] = {};
    int32_t col_xx_[MaxWidth] = {}, col_xy_[MaxWidth] = {}, col_yy_[MaxWidth] = {};
    int64_t resp_[3][MaxWidth] = {};
    uint8_t pixels_[static_cast<unsigned>(kPixelRows)][MaxWidth] = {};
    // During a frame cell c owns items[c·per_cell, (c+1)·per_cell); finish() sorts them.
    FeatureSet<PatchRadius, MaxFeatures> kept_;
    uint8_t cell_count_[MaxFeatures] = {};  // cells <= slots <= MaxFeatures
    HarrisParams config_;
    HarrisStats stats_;
    uint16_t width_ = 0, height_ = 0, pixel_rows_ = 0, gradient_rows_ = 0;
    int filled_ = 0;  // consecutive needed rows in the column sums, counted up to 2V+3
    bool in_frame_ = false;
};

// A whole frame in memory (row-major, `stride` bytes a row) through a GradientStage (on the
// stack: 6·MaxWidth bytes) and the detector, in the order the detector requires. Returns the
// first status that is not ok (out.count = 0 then), else finish()'s.
template <uint16_t MaxWidth, uint16_t MaxFeatures, int PatchRadius, int WindowRadius>
Status detect_features(HarrisDetector<MaxWidth, MaxFeatures, PatchRadius, WindowRadius>& det,
                       const uint8_t* frame, uint16_t width, uint16_t height, uint32_t stride,
                       const HarrisParams& config, FeatureSet<PatchRadius, MaxFeatures>& out) {
    out.count = 0;
    Status s = det.begin_frame(width, height, config);
    if (s == Status::previous_frame_incomplete) s = Status::ok;
    GradientStage<MaxWidth> stage;
    if (s == Status::ok) s = stage.begin_frame(width, height);
    Status sink_status = Status::ok;
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t w) {
        const Status g = det.push_gradient_row(y, words, w);
        if (sink_status == Status::ok) sink_status = g;
    };
    for (uint16_t y = 0; y < height && s == Status::ok; ++y) {
        const uint8_t* row = frame + size_t{y} * stride;
        s = det.push_pixel_row(row, width);
        if (s == Status::ok) s = stage.push_row(row, width, sink);
        if (s == Status::ok) s = sink_status;
    }
    if (s != Status::ok) {
        det.finish(out);  // ends the frame
        out.count = 0;
        return s;
    }
    return det.finish(out);
}

}  // namespace qt

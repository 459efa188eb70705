// Table III step 2 as the Filtering and Geometry paper describes it: "detect target candidate from
// interest region ... by using morphological operation and clustering" (its reference [9]: a
// top-hat filter and clustering of the detections). The alternative to the NCC template
// (template_search.h) as the target tracker's measurement. Integer only.
//
//   1. Top-hat in the search window: the window minus its grey opening (a bright target) or
//      its grey closing minus the window (a dark one), with a square structuring element of
//      `element` px, a side larger than the target: what survives is what is smaller than the
//      element and brighter (darker) than its surroundings.
//   2. Detections: top-hat >= max(min_contrast, peak / 2) (peak: the window's largest top-hat).
//   3. Clustering: 8-connected detections (runs of a row joined to the touching runs of the
//      row above, union-find); each cluster's area and top-hat-weighted centroid.
//   4. The candidate: among clusters of area within [min_area, max_area], the one whose
//      centroid is nearest the window's centre (the tracker's gates decide whether it is the
//      target).
//
// Memory: one MaxW × MaxH byte buffer (the opening, in place) and a run table of MaxRuns.
// Work: 4 · element comparisons a pixel of the window, then one pass for the runs.
#pragma once
#include <stdint.h>

#include "base/floor_div.h"
#include "target/template_search.h"  // PixelRegion

namespace qt {

enum class Polarity : uint8_t { bright, dark };

struct MorphParams {
    uint8_t element = 17;       // side of the square structuring element, px (odd, 3..63)
    uint8_t min_contrast = 12;  // a detection's top-hat at least this, grey levels
    uint16_t min_area = 4, max_area = 1024;  // a candidate cluster's pixels
};

struct MorphDetection {
    bool found = false;
    int32_t x_q8 = 0, y_q8 = 0;  // the chosen cluster's centroid (top-hat weighted), 1/256 px
    uint16_t area = 0;           // its pixels
    uint16_t clusters = 0;       // clusters in the window (any area)
    bool runs_full = false;      // the run table filled: clusters may be incomplete
};

template <uint16_t MaxW, uint16_t MaxH, uint16_t MaxRuns = 256>
class MorphDetector {
    // Σ top-hat · x over the window in int32: 255 · MaxW · MaxH · MaxW < 2^31.
    static_assert(uint64_t{255} * MaxW * MaxH * (MaxW > MaxH ? MaxW : MaxH) < (uint64_t{1} << 31),
                  "window sums fit int32");
    static_assert(uint32_t{MaxW} * MaxH <= 65535, "areas fit uint16");

public:
    // Detects in the candidates' window: centres within ±radius px of (cx, cy), the window
    // widened by the element so the opening sees the target's surroundings, clipped to the
    // region and to MaxW × MaxH.
    MorphDetection detect(const PixelRegion& region, int32_t cx, int32_t cy, uint16_t radius,
                          Polarity polarity, const MorphParams& p) {
        MorphDetection out;
        const int32_t e = p.element < 3 ? 3 : p.element > 63 ? 63 : p.element;
        const uint8_t* src = load_window(region, cx, cy, static_cast<int32_t>(radius) + e / 2 + 1);
        if (src == nullptr) return out;
        // Opening = dilate(erode(I)); closing = erode(dilate(I)).
        const bool bright = polarity == Polarity::bright;
        filter(e, bright);   // erode for the opening, dilate for the closing
        filter(e, !bright);  // then the other
        const int32_t half = tophat_peak(src, region.stride, bright) / 2;
        const int32_t thr = half > p.min_contrast ? half : p.min_contrast;
        const uint16_t n = label_runs(src, region.stride, bright, thr, out);
        sum_into_roots(n);
        nearest_cluster(n, cx, cy, radius, p, out);
        return out;
    }

private:
    // Copies the window of centres within ±reach px of (cx, cy), clipped to the region and to
    // MaxW × MaxH, into buf_; returns the window's first pixel in the region, or null when
    // nothing is left.
    const uint8_t* load_window(const PixelRegion& region, int32_t cx, int32_t cy, int32_t reach) {
        int64_t x0 = int64_t{cx} - reach, y0 = int64_t{cy} - reach;
        int64_t x1 = int64_t{cx} + reach + 1, y1 = int64_t{cy} + reach + 1;  // exclusive
        if (x0 < region.x0) x0 = region.x0;
        if (y0 < region.y0) y0 = region.y0;
        if (x1 > int64_t{region.x0} + region.w) x1 = int64_t{region.x0} + region.w;
        if (y1 > int64_t{region.y0} + region.h) y1 = int64_t{region.y0} + region.h;
        if (x1 - x0 > MaxW) x1 = x0 + MaxW;
        if (y1 - y0 > MaxH) y1 = y0 + MaxH;
        if (x1 <= x0 || y1 <= y0 || region.pixels == nullptr) return nullptr;
        wx0_ = static_cast<int32_t>(x0);
        wy0_ = static_cast<int32_t>(y0);
        w_ = static_cast<int32_t>(x1 - x0);
        h_ = static_cast<int32_t>(y1 - y0);
        const uint8_t* src = region.pixels +
                             static_cast<uint32_t>(wy0_ - region.y0) * region.stride +
                             static_cast<uint32_t>(wx0_ - region.x0);
        for (int32_t y = 0; y < h_; ++y)
            for (int32_t x = 0; x < w_; ++x)
                buf_[y * MaxW + x] =
                    src[static_cast<uint32_t>(y) * region.stride + static_cast<uint32_t>(x)];
        return src;
    }

    int32_t tophat_peak(const uint8_t* src, uint32_t stride, bool bright) const {
        int32_t peak = 0;
        for (int32_t y = 0; y < h_; ++y)
            for (int32_t x = 0; x < w_; ++x) {
                const int32_t t = tophat(src, stride, x, y, bright);
                peak = t > peak ? t : peak;
            }
        return peak;
    }

    // Runs of detections (top-hat ≥ thr), each joined to the touching runs of the row above
    // (8-connected); returns how many runs_ holds.
    uint16_t label_runs(const uint8_t* src, uint32_t stride, bool bright, int32_t thr,
                        MorphDetection& out) {
        uint16_t n = 0;
        uint16_t prev_first = 0, prev_end = 0;  // the row above's runs
        for (int32_t y = 0; y < h_; ++y) {
            const uint16_t row_first = n;
            int32_t x = 0;
            while (x < w_) {
                if (tophat(src, stride, x, y, bright) < thr) {
                    ++x;
                    continue;
                }
                const int32_t start = x;
                int32_t sw = 0, sx = 0, sy = 0;
                for (; x < w_; ++x) {
                    const int32_t t = tophat(src, stride, x, y, bright);
                    if (t < thr) break;
                    sw += t;
                    sx += t * x;
                    sy += t * y;
                }
                if (n == MaxRuns) {
                    out.runs_full = true;
                    continue;
                }
                Run& r = runs_[n];
                r.x0 = static_cast<int16_t>(start);
                r.x1 = static_cast<int16_t>(x - 1);
                r.parent = n;
                r.area = static_cast<uint16_t>(x - start);
                r.sw = sw;
                r.sx = sx;
                r.sy = sy;
                for (uint16_t k = prev_first; k < prev_end; ++k)
                    if (runs_[k].x1 >= start - 1 && runs_[k].x0 <= x) unite(k, n);
                ++n;
            }
            prev_first = row_first;
            prev_end = n;
        }
        return n;
    }

    // Each run's sums added into its cluster's root.
    void sum_into_roots(uint16_t n) {
        for (uint16_t i = 0; i < n; ++i) {
            const uint16_t r = find(i);
            if (r == i) continue;
            runs_[r].area = static_cast<uint16_t>(runs_[r].area + runs_[i].area);
            runs_[r].sw += runs_[i].sw;
            runs_[r].sx += runs_[i].sx;
            runs_[r].sy += runs_[i].sy;
        }
    }

    // The candidate: the cluster of an area within the limits whose centroid lies within
    // ±radius px of (cx, cy) and nearest it (ties: the first in raster order).
    void nearest_cluster(uint16_t n, int32_t cx, int32_t cy, uint16_t radius, const MorphParams& p,
                         MorphDetection& out) const {
        int64_t best_d = -1;
        const int64_t ccx = int64_t{cx} - wx0_, ccy = int64_t{cy} - wy0_;
        for (uint16_t i = 0; i < n; ++i) {
            if (runs_[i].parent != i) continue;
            ++out.clusters;
            const Run& r = runs_[i];
            if (r.area < p.min_area || r.area > p.max_area || r.sw <= 0) continue;
            // Centroid in 1/256 px, rounded to nearest (ties up): (256·Σtx + Σt/2) / Σt.
            const int64_t qx = floor_div(256 * int64_t{r.sx} + r.sw / 2, r.sw);
            const int64_t qy = floor_div(256 * int64_t{r.sy} + r.sw / 2, r.sw);
            const int64_t dx = qx - 256 * ccx, dy = qy - 256 * ccy;
            const int64_t lim = 256 * int64_t{radius};
            if (dx < -lim || dx > lim || dy < -lim || dy > lim) continue;  // not a candidate centre
            const int64_t d = dx * dx + dy * dy;
            if (best_d >= 0 && d >= best_d) continue;
            best_d = d;
            out.found = true;
            out.x_q8 = static_cast<int32_t>(qx + 256 * int64_t{wx0_});
            out.y_q8 = static_cast<int32_t>(qy + 256 * int64_t{wy0_});
            out.area = r.area;
        }
    }

    struct Run {
        int16_t x0 = 0, x1 = 0;  // first and last column, window px
        uint16_t parent = 0;
        uint16_t area = 0;
        int32_t sw = 0, sx = 0, sy = 0;  // Σ top-hat, Σ top-hat·x, Σ top-hat·y (window px)
    };

    uint16_t find(uint16_t i) {
        while (runs_[i].parent != i) {
            runs_[i].parent = runs_[runs_[i].parent].parent;  // path halving
            i = runs_[i].parent;
        }
        return i;
    }
    void unite(uint16_t a, uint16_t b) {
        const uint16_t ra = find(a), rb = find(b);
        if (ra == rb) return;
        if (ra < rb)  // the earlier run is the root, so the result does not depend on order
            runs_[rb].parent = ra;
        else
            runs_[ra].parent = rb;
    }

    // Top-hat at window pixel (x, y): I − opening (bright) or closing − I (dark), >= 0.
    int32_t tophat(const uint8_t* src, uint32_t stride, int32_t x, int32_t y, bool bright) const {
        const int32_t i = src[static_cast<uint32_t>(y) * stride + static_cast<uint32_t>(x)];
        const int32_t m = buf_[y * MaxW + x];
        const int32_t t = bright ? i - m : m - i;
        return t > 0 ? t : 0;
    }

    // One separable square min (erode) or max (dilate) filter of side e over the window, in
    // place; the window's border clips the element (pixels outside are not part of the set).
    void filter(int32_t e, bool min) {
        const int32_t r = e / 2;
        uint8_t line[MaxW > MaxH ? MaxW : MaxH];
        for (int32_t y = 0; y < h_; ++y) {
            for (int32_t x = 0; x < w_; ++x) line[x] = buf_[y * MaxW + x];
            for (int32_t x = 0; x < w_; ++x)
                buf_[y * MaxW + x] =
                    extreme(line, x - r < 0 ? 0 : x - r, x + r >= w_ ? w_ - 1 : x + r, min);
        }
        for (int32_t x = 0; x < w_; ++x) {
            for (int32_t y = 0; y < h_; ++y) line[y] = buf_[y * MaxW + x];
            for (int32_t y = 0; y < h_; ++y)
                buf_[y * MaxW + x] =
                    extreme(line, y - r < 0 ? 0 : y - r, y + r >= h_ ? h_ - 1 : y + r, min);
        }
    }
    static uint8_t extreme(const uint8_t* v, int32_t a, int32_t b, bool min) {
        uint8_t m = v[a];
        for (int32_t k = a + 1; k <= b; ++k)
            m = min ? (v[k] < m ? v[k] : m) : (v[k] > m ? v[k] : m);
        return m;
    }

    uint8_t buf_[static_cast<uint32_t>(MaxW) * MaxH] = {};
    Run runs_[MaxRuns] = {};
    int32_t wx0_ = 0, wy0_ = 0, w_ = 0, h_ = 0;
};

// Stands in for MorphDetector in a build whose capacity leaves it out (morph_region 0):
// nothing stored, nothing found. TargetPipeline refuses the morphological option first.
struct MorphDetectorLeftOut {
    MorphDetection detect(const PixelRegion&, int32_t, int32_t, uint16_t, Polarity,
                          const MorphParams&) const {
        return MorphDetection{};
    }
};

}  // namespace qt

// Harris corners (core/target/harris.h) against a whole-image double-precision Harris written here
// from the definition (gradients, box-summed tensor, response, NMS rule, parabola), and
// hand-worked scenes; bucketing, capacity, row order and sizes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "base/prng.h"
#include "gradient/gradient_stage.h"
#include "target/harris.h"

using namespace qt;

namespace {

struct Image {
    int w = 0, h = 0;
    std::vector<uint8_t> px;
    Image(int w_, int h_, uint8_t v) : w(w_), h(h_), px(static_cast<size_t>(w_ * h_), v) {}
    uint8_t& at(int x, int y) { return px[static_cast<size_t>(y * w + x)]; }
    int get(int x, int y) const {  // replicated borders
        x = std::min(std::max(x, 0), w - 1);
        y = std::min(std::max(y, 0), h - 1);
        return px[static_cast<size_t>(y * w + x)];
    }
};

void fill_rect(Image& im, int x0, int y0, int x1, int y1, int v) {
    for (int y = std::max(y0, 0); y <= std::min(y1, im.h - 1); ++y)
        for (int x = std::max(x0, 0); x <= std::min(x1, im.w - 1); ++x)
            im.at(x, y) = static_cast<uint8_t>(std::min(std::max(v, 0), 255));
}

// Random rectangles of random grey levels on a mid-grey ground, plus ±2 grey levels of noise.
Image rect_texture(int w, int h, uint64_t seed, int rects) {
    Image im(w, h, 128);
    Pcg32 rng(seed);
    for (int i = 0; i < rects; ++i) {
        const int x0 = static_cast<int>(rng.below(static_cast<uint32_t>(w))),
                  y0 = static_cast<int>(rng.below(static_cast<uint32_t>(h)));
        const int rw = 4 + static_cast<int>(rng.below(18)),
                  rh = 4 + static_cast<int>(rng.below(18));
        fill_rect(im, x0, y0, x0 + rw, y0 + rh, static_cast<int>(rng.below(256)));
    }
    for (auto& p : im.px)
        p = static_cast<uint8_t>(
            std::min(std::max(p + static_cast<int>(rng.below(5)) - 2, 0), 255));
    return im;
}

struct RefCorner {
    int x, y;
    double response, fx, fy;  // fx, fy: sub-pixel position, px
};

// The response at (x, y) from the definition, in double: central differences with replicated
// borders, M summed directly over the (2V+1)² box, 25·det − trace² (exact: every value < 2^53).
double ref_response(const Image& im, int x, int y, int V) {
    double a = 0, b = 0, c = 0;
    for (int v = -V; v <= V; ++v)
        for (int u = -V; u <= V; ++u) {
            const double X = im.get(x + u + 1, y + v) - im.get(x + u - 1, y + v);
            const double Y = im.get(x + u, y + v + 1) - im.get(x + u, y + v - 1);
            a += X * X;
            b += X * Y;
            c += Y * Y;
        }
    return 25 * (a * c - b * b) - (a + c) * (a + c);
}

// Harris from the definition: ref_response, maxima strictly above the earlier 3×3 neighbours
// and >= the later ones, at least max(R, V+1) px from the border, response >= floor and > 0.
std::vector<RefCorner> ref_harris(const Image& im, int V, int R, double floor) {
    const int w = im.w, h = im.h;
    std::vector<double> resp(static_cast<size_t>(w * h), -1e300);
    auto idx = [w](int x, int y) { return static_cast<size_t>(y * w + x); };
    for (int y = V; y < h - V; ++y)
        for (int x = V; x < w - V; ++x) resp[idx(x, y)] = ref_response(im, x, y, V);
    const int border = std::max(R, V + 1);
    std::vector<RefCorner> out;
    for (int y = border; y < h - border; ++y)
        for (int x = border; x < w - border; ++x) {
            const double r = resp[idx(x, y)];
            bool is_max = r > 0 && r >= floor;
            for (int v = -1; v <= 1; ++v)
                for (int u = -1; u <= 1; ++u) {
                    if (u == 0 && v == 0) continue;
                    const double n = resp[idx(x + u, y + v)];
                    const bool earlier = v < 0 || (v == 0 && u < 0);
                    if (earlier ? !(r > n) : !(r >= n)) is_max = false;
                }
            if (!is_max) continue;
            const double l = resp[idx(x - 1, y)], rr = resp[idx(x + 1, y)];
            const double t = resp[idx(x, y - 1)], bo = resp[idx(x, y + 1)];
            out.push_back({x, y, r, x + (l - rr) / (2 * (l - 2 * r + rr)),
                           y + (t - bo) / (2 * (t - 2 * r + bo))});
        }
    std::sort(out.begin(), out.end(), [](const RefCorner& p, const RefCorner& q) {
        if (p.response != q.response) return p.response > q.response;
        return p.y != q.y ? p.y < q.y : p.x < q.x;
    });
    return out;
}

HarrisParams config(int64_t floor, int cols, int rows, int per_cell) {
    HarrisParams c;
    c.min_response = floor;
    c.grid_cols = static_cast<uint8_t>(cols);
    c.grid_rows = static_cast<uint8_t>(rows);
    c.per_cell = static_cast<uint8_t>(per_cell);
    return c;
}

template <uint16_t MW, uint16_t MF, int R, int V>
Status detect(HarrisDetector<MW, MF, R, V>& det, const Image& im, const HarrisParams& c,
              FeatureSet<R, MF>& out) {
    return detect_features(det, im.px.data(), static_cast<uint16_t>(im.w),
                           static_cast<uint16_t>(im.h), static_cast<uint32_t>(im.w), c, out);
}

template <int R>
void require_patch(const Feature<R>& f, const Image& im) {
    for (int v = -R; v <= R; ++v)
        for (int u = -R; u <= R; ++u)
            REQUIRE(f.patch[(v + R) * Feature<R>::kSide + u + R] == im.get(f.px + u, f.py + v));
}

// round(256·v) half away from zero; within 1 only where 256·v is within 10^-6 of a half (the
// double parabola is inexact there, the detector's rational is exact).
void require_q8(int32_t got, double v) {
    const double x = 256 * v, frac = std::abs(x - std::trunc(x));
    if (std::abs(frac - 0.5) < 1e-6)
        REQUIRE(std::abs(got - std::lround(x)) <= 1);
    else
        REQUIRE(got == std::lround(x));
}

// Detector output == reference corners (position, response, patch, sub-pixel).
template <int R, uint16_t MF>
void require_same(const FeatureSet<R, MF>& got, const std::vector<RefCorner>& want,
                  const Image& im) {
    REQUIRE(got.count == want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        const Feature<R>& f = got.items[i];
        INFO("corner " << i << " at " << want[i].x << "," << want[i].y);
        REQUIRE(f.px == want[i].x);
        REQUIRE(f.py == want[i].y);
        REQUIRE(f.response == static_cast<int64_t>(want[i].response));
        require_q8(f.x_q8, want[i].fx);
        require_q8(f.y_q8, want[i].fy);
        require_patch(f, im);
    }
}

// All gradient rows of a frame, in order, from a GradientStage.
std::vector<std::vector<gradient_word>> gradient_rows(const Image& im) {
    GradientStage<256> stage;
    std::vector<std::vector<gradient_word>> rows;
    REQUIRE(stage.begin_frame(static_cast<uint16_t>(im.w), static_cast<uint16_t>(im.h)) ==
            Status::ok);
    for (int y = 0; y < im.h; ++y)
        REQUIRE(stage.push_row(&im.px[static_cast<size_t>(y * im.w)], static_cast<uint16_t>(im.w),
                               [&](uint16_t, const gradient_word* g, uint16_t n) {
                                   rows.emplace_back(g, g + n);
                               }) == Status::ok);
    return rows;
}

}  // namespace

TEST_CASE("Harris equals a double-precision Harris on a textured frame", "[harris]") {
    for (uint64_t seed : {1u, 2u, 3u}) {
        const Image im = rect_texture(120, 90, seed, 30);
        const auto want = ref_harris(im, 2, 4, 1e7);
        INFO("seed " << seed << ", " << want.size() << " corners");
        REQUIRE(want.size() >= 20);
        REQUIRE(want.size() <= 255);
        static HarrisDetector<128, 255, 4, 2> det;
        static FeatureSet<4, 255> out;
        REQUIRE(detect(det, im, config(10000000, 1, 1, 255), out) == Status::ok);
        require_same(out, want, im);
        REQUIRE(det.stats().candidates == want.size());
        REQUIRE(det.stats().replaced == 0);
        REQUIRE(det.stats().dropped == 0);
        REQUIRE(out.width == 120);
        REQUIRE(out.height == 90);
    }
}

TEST_CASE("Harris with other patch and window radii equals the reference", "[harris]") {
    const Image im = rect_texture(100, 70, 9, 25);
    {
        static HarrisDetector<128, 200, 2, 1> det;  // R < V + 1: patches complete when found
        static FeatureSet<2, 200> out;
        const auto want = ref_harris(im, 1, 2, 1e6);
        REQUIRE(want.size() >= 20);
        REQUIRE(want.size() <= 200);
        REQUIRE(detect(det, im, config(1000000, 1, 1, 200), out) == Status::ok);
        require_same(out, want, im);
    }
    {
        static HarrisDetector<128, 200, 7, 3> det;  // R > V + 1: rows copied as they arrive
        static FeatureSet<7, 200> out;
        const auto want = ref_harris(im, 3, 7, 1e8);
        REQUIRE(want.size() >= 10);
        REQUIRE(want.size() <= 200);
        REQUIRE(detect(det, im, config(100000000, 1, 1, 200), out) == Status::ok);
        require_same(out, want, im);
    }
}

TEST_CASE("Harris ties: plateaus of equal responses give the corner the tie rule names",
          "[harris]") {
    // Dots of even width and height, each symmetric about the line between its two middle
    // columns (and rows): the responses there come in exactly equal pairs, and the rule (above
    // the earlier neighbours, at least the later ones) names the plateau's first pixel in
    // raster order. Widths 2..6 at several contrasts, against the double-precision reference.
    Image im(96, 64, 90);
    int dot = 0;
    for (int w : {2, 4, 6})
        for (int h : {2, 4}) {
            const int x0 = 10 + 28 * (dot % 3), y0 = 12 + 28 * (dot / 3);
            fill_rect(im, x0, y0, x0 + w - 1, y0 + h - 1, 90 + 40 + 30 * dot);
            ++dot;
        }
    const auto want = ref_harris(im, 2, 4, 1e7);
    REQUIRE(want.size() >= 6);
    int tied = 0;  // corners whose right-hand neighbour has the same response
    for (const RefCorner& k : want) tied += ref_response(im, k.x + 1, k.y, 2) == k.response;
    REQUIRE(tied >= 3);
    static HarrisDetector<128, 255, 4, 2> det;
    static FeatureSet<4, 255> out;
    REQUIRE(detect(det, im, config(10000000, 1, 1, 255), out) == Status::ok);
    require_same(out, want, im);
}

TEST_CASE("Harris on a bright square: its four corners, worked by hand", "[harris]") {
    // A square of pixels 20..43 on a dark ground, contrast C. Near its top-left corner gx = C
    // at columns 19 and 20 from row 20 down, gy = C at rows 19 and 20 from column 20 right,
    // both only at (20, 20). The 5×5 window centred on (21, 21) holds 8 gx and 8 gy pixels,
    // so Sxx = Syy = 8C², Sxy = C², response = 25·63·C⁴ − 256·C⁴ = 1319·C⁴; at (20, 21):
    // Sxx = 6C², Syy = 8C² → 979·C⁴; at (22, 21): Sxx = 4C², Syy = 10C² → 779·C⁴; the column
    // above and below alike by symmetry. The peak is (21, 21) (the box window pulls it inside
    // the square), the parabola's vertex 21 + (779 − 979)/(2·(2·1319 − 979 − 779)) = 21 − 0.114
    // px: 21·256 − round(29.09) = 5347 in 1/256 px. The other corners mirror it about 31.5.
    for (int64_t contrast : {170, 20, 1}) {
        Image im(64, 64, 40);
        fill_rect(im, 20, 20, 43, 43, 40 + static_cast<int>(contrast));
        static HarrisDetector<64, 16, 4, 2> det;
        static FeatureSet<4, 16> out;
        REQUIRE(detect(det, im, config(1, 2, 2, 4), out) == Status::ok);
        REQUIRE(out.count == 4);
        int found[2][2] = {};
        for (uint16_t i = 0; i < 4; ++i) {
            const Feature<4>& f = out.items[i];
            INFO("corner " << f.px << "," << f.py << " sub-pixel " << f.x_q8 / 256.0 << ","
                           << f.y_q8 / 256.0);
            const int right = f.px > 32, bottom = f.py > 32;
            ++found[right][bottom];
            REQUIRE(f.px == (right ? 42 : 21));
            REQUIRE(f.py == (bottom ? 42 : 21));
            REQUIRE(f.x_q8 == (right ? 63 * 256 - 5347 : 5347));
            REQUIRE(f.y_q8 == (bottom ? 63 * 256 - 5347 : 5347));
            REQUIRE(f.response == 1319 * contrast * contrast * contrast * contrast);
            require_patch(f, im);
        }
        REQUIRE((found[0][0] == 1 && found[0][1] == 1 && found[1][0] == 1 && found[1][1] == 1));
        // Strength order on equal responses: by y, then x.
        REQUIRE((out.items[0].px == 21 && out.items[0].py == 21 && out.items[1].px == 42 &&
                 out.items[1].py == 21));
    }
}

TEST_CASE("Harris default floor drops a corner of contrast 8 and keeps one of 11", "[harris]") {
    // 1319·C⁴ (above): 5.4·10^6 at C = 8, 1.9·10^7 at C = 11; the floor is 10^7.
    for (int contrast : {8, 11}) {
        Image im(48, 48, 100);
        fill_rect(im, 24, 24, 47, 47, 100 + contrast);  // one corner at (24, 24)
        static HarrisDetector<64, 96, 4, 2> det;
        static FeatureSet<4, 96> out;
        REQUIRE(detect(det, im, HarrisParams{}, out) == Status::ok);
        REQUIRE(out.count == (contrast == 11 ? 1 : 0));
        REQUIRE(det.stats().weak == (contrast == 11 ? 0u : 1u));
    }
}

TEST_CASE("Harris rows in any order the contract allows give the same corners", "[harris]") {
    const Image im = rect_texture(100, 60, 4, 25);
    const auto grads = gradient_rows(im);
    static HarrisDetector<128, 255, 4, 2> det;
    static FeatureSet<4, 255> ref_out, out;
    const HarrisParams c = config(1000000, 1, 1, 255);
    REQUIRE(detect(det, im, c, ref_out) == Status::ok);
    REQUIRE(ref_out.count >= 20);
    for (int lag : {0, 1, 2}) {  // gradient row y right after pixel row y + lag
        REQUIRE(det.begin_frame(100, 60, c) == Status::ok);
        int next_grad = 0;
        for (int y = 0; y < im.h; ++y) {
            REQUIRE(det.push_pixel_row(&im.px[static_cast<size_t>(y * im.w)], 100) == Status::ok);
            for (; next_grad <= y - lag; ++next_grad)
                REQUIRE(det.push_gradient_row(static_cast<uint16_t>(next_grad),
                                              grads[static_cast<size_t>(next_grad)].data(),
                                              100) == Status::ok);
        }
        for (; next_grad < im.h; ++next_grad)
            REQUIRE(det.push_gradient_row(static_cast<uint16_t>(next_grad),
                                          grads[static_cast<size_t>(next_grad)].data(),
                                          100) == Status::ok);
        REQUIRE(det.finish(out) == Status::ok);
        REQUIRE(out.count == ref_out.count);
        for (uint16_t i = 0; i < out.count; ++i) {
            REQUIRE(out.items[i].x_q8 == ref_out.items[i].x_q8);
            REQUIRE(out.items[i].y_q8 == ref_out.items[i].y_q8);
            REQUIRE(out.items[i].response == ref_out.items[i].response);
            require_patch(out.items[i], im);
        }
    }
}

TEST_CASE(
    "Harris in bands finds the reference's corners of the bands' rows and reads no other "
    "gradient row",
    "[harris]") {
    // 120 × 90 in 3 cell rows of 30 rows; a band of b rows is rows [30j + (30 − b)/2, + b) of
    // cell row j. The reference: the double Harris's corners (every row), those in a band kept.
    // Gradient rows more than V + 1 = 3 rows from every band row are replaced by noise: no
    // response, and no suppression, may read them.
    const Image im = rect_texture(120, 90, 6, 30);
    const auto all = ref_harris(im, 2, 4, 1e7);
    const auto clean = gradient_rows(im);
    static HarrisDetector<128, 255, 4, 2> det;
    static FeatureSet<4, 255> out;
    for (int band : {0, 5, 12, 29, 30}) {
        auto in_band = [&](int y) {
            if (band == 0 || band >= 30) return true;
            const int first = y / 30 * 30 + (30 - band) / 2;
            return y >= first && y < first + band;
        };
        std::vector<RefCorner> want;
        for (const RefCorner& c : all)
            if (in_band(c.y)) want.push_back(c);
        INFO("band " << band << ": " << want.size() << " corners");
        REQUIRE(want.size() >= (band == 5 ? 3u : 10u));
        auto grads = clean;
        Pcg32 rng(static_cast<uint64_t>(band) + 1);
        int noisy = 0;
        for (int y = 0; y < im.h; ++y) {
            bool near = false;
            for (int r = y - 3; r <= y + 3; ++r) near = near || (r >= 0 && r < im.h && in_band(r));
            if (near) continue;
            ++noisy;
            for (auto& w : grads[static_cast<size_t>(y)])
                w = make_gradient_word_xy(static_cast<int32_t>(rng.below(511)) - 255,
                                          static_cast<int32_t>(rng.below(511)) - 255);
        }
        if (band == 5) REQUIRE(noisy > 40);
        HarrisParams c = config(10000000, 1, 3, 85);
        c.band_rows = static_cast<uint16_t>(band);
        REQUIRE(det.begin_frame(120, 90, c) == Status::ok);
        for (int y = 0; y < im.h; ++y) {
            REQUIRE(det.push_pixel_row(&im.px[static_cast<size_t>(y * im.w)], 120) == Status::ok);
            REQUIRE(det.push_gradient_row(static_cast<uint16_t>(y),
                                          grads[static_cast<size_t>(y)].data(), 120) == Status::ok);
        }
        REQUIRE(det.finish(out) == Status::ok);
        require_same(out, want, im);
    }
}

TEST_CASE("Harris bucketing keeps the per_cell strongest of each cell, strongest first",
          "[harris]") {
    const Image im = rect_texture(120, 90, 5, 40);
    const auto all = ref_harris(im, 2, 4, 1e6);
    const int cols = 4, rows = 3, per_cell = 2;
    // Reference bucketing: all corners of a cell ranked, the first per_cell kept.
    std::vector<RefCorner> want;
    std::vector<int> in_cell(cols * rows, 0);
    for (const RefCorner& r : all) {  // `all` is already in strength order
        const int cell = (r.y * rows / im.h) * cols + r.x * cols / im.w;
        if (in_cell[static_cast<size_t>(cell)]++ < per_cell) want.push_back(r);
    }
    static HarrisDetector<128, 24, 4, 2> det;
    static FeatureSet<4, 24> out;
    REQUIRE(detect(det, im, config(1000000, cols, rows, per_cell), out) == Status::ok);
    require_same(out, want, im);
    int full_cells = 0;
    for (int n : in_cell) full_cells += n >= per_cell;
    REQUIRE(full_cells >= 10);  // the features spread over the frame
    const HarrisStats& s = det.stats();
    REQUIRE(s.candidates == all.size());
    REQUIRE(s.candidates - s.replaced - s.dropped == out.count);
    REQUIRE(s.replaced + s.dropped > 0);
}

TEST_CASE("Harris capacity: MaxFeatures of the strongest, over-large grids refused", "[harris]") {
    const Image im = rect_texture(120, 90, 6, 40);
    const auto all = ref_harris(im, 2, 4, 1e6);
    REQUIRE(all.size() > 8);
    static HarrisDetector<128, 8, 4, 2> det;
    static FeatureSet<4, 8> out;
    REQUIRE(detect(det, im, config(1000000, 1, 1, 8), out) == Status::ok);
    require_same(out, std::vector<RefCorner>(all.begin(), all.begin() + 8), im);
    REQUIRE(det.stats().replaced + det.stats().dropped == all.size() - 8);
    // The default 8×6×2 grid needs 96 slots.
    REQUIRE(det.begin_frame(120, 90, HarrisParams{}) == Status::bad_size);
    REQUIRE(det.begin_frame(120, 90, config(1, 3, 1, 3)) == Status::bad_size);
    REQUIRE(det.begin_frame(120, 90, config(1, 0, 1, 1)) == Status::bad_size);
    REQUIRE(det.begin_frame(120, 90, config(1, 1, 1, 0)) == Status::bad_size);
    REQUIRE(det.finish(out) == Status::not_in_frame);
    REQUIRE(out.count == 0);
}

TEST_CASE("Harris sizes and lengths", "[harris]") {
    static HarrisDetector<64, 96, 4, 2> det;
    static FeatureSet<4, 96> out;
    const HarrisParams c;
    REQUIRE(det.begin_frame(0, 10, c) == Status::bad_size);
    REQUIRE(det.begin_frame(10, 0, c) == Status::bad_size);
    REQUIRE(det.begin_frame(65, 10, c) == Status::bad_size);
    REQUIRE(det.begin_frame(64, 40000, c) == Status::bad_size);
    std::vector<uint8_t> row(64, 7);
    REQUIRE(det.push_pixel_row(row.data(), 64) == Status::not_in_frame);
    std::vector<gradient_word> grad(64, 0);
    REQUIRE(det.begin_frame(64, 10, c) == Status::ok);
    REQUIRE(det.push_pixel_row(row.data(), 64) == Status::ok);
    REQUIRE(det.begin_frame(64, 10, c) == Status::previous_frame_incomplete);
    REQUIRE(det.push_pixel_row(row.data(), 63) == Status::bad_row_length);
    REQUIRE(det.push_pixel_row(row.data(), 64) == Status::not_in_frame);
    REQUIRE(det.begin_frame(64, 10, c) == Status::ok);
    REQUIRE(det.push_pixel_row(row.data(), 64) == Status::ok);
    REQUIRE(det.push_gradient_row(0, grad.data(), 65) == Status::bad_row_length);
    REQUIRE(det.finish(out) == Status::not_in_frame);
    // A tiny frame: no room for a corner, still a frame.
    Image tiny(3, 2, 9);
    static HarrisDetector<64, 96, 4, 2> det2;
    REQUIRE(detect(det2, tiny, c, out) == Status::ok);
    REQUIRE(out.count == 0);
}

TEST_CASE("Harris row-order violations give bad_row_order and abandon the frame", "[harris]") {
    static HarrisDetector<64, 96, 4, 2> det;
    static FeatureSet<4, 96> out;
    const HarrisParams c;
    std::vector<uint8_t> row(16, 7);
    std::vector<gradient_word> grad(16, 0);
    SECTION("gradient row before its pixel row") {
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        REQUIRE(det.push_gradient_row(0, grad.data(), 16) == Status::bad_row_order);
    }
    SECTION("pixel row y + 3 before gradient row y") {
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        for (int y = 0; y < 3; ++y) REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::bad_row_order);
    }
    SECTION("a gradient row skipped") {
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
        REQUIRE(det.push_gradient_row(1, grad.data(), 16) == Status::bad_row_order);
    }
    SECTION("a gradient row repeated") {
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
        REQUIRE(det.push_gradient_row(0, grad.data(), 16) == Status::ok);
        REQUIRE(det.push_gradient_row(0, grad.data(), 16) == Status::bad_row_order);
    }
    SECTION("finish with rows missing") {
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        for (int y = 0; y < 8; ++y)
            REQUIRE(det.push_pixel_row(row.data(), 16) == (y < 3    ? Status::ok
                                                           : y == 3 ? Status::bad_row_order
                                                                    : Status::not_in_frame));
        REQUIRE(det.finish(out) == Status::not_in_frame);
        REQUIRE(det.begin_frame(16, 8, c) == Status::ok);
        for (int y = 0; y < 8; ++y) {
            REQUIRE(det.push_pixel_row(row.data(), 16) == Status::ok);
            if (y < 7)
                REQUIRE(det.push_gradient_row(static_cast<uint16_t>(y), grad.data(), 16) ==
                        Status::ok);
        }
        REQUIRE(det.push_pixel_row(row.data(), 16) == Status::not_in_frame);  // past the last
        REQUIRE(det.finish(out) == Status::not_in_frame);  // gradient row 7 missing
    }
    REQUIRE_FALSE(det.in_frame());
    REQUIRE(det.push_pixel_row(row.data(), 16) == Status::not_in_frame);
    REQUIRE(det.finish(out) == Status::not_in_frame);
    REQUIRE(out.count == 0);
}

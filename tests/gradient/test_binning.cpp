// The binning stage (core/gradient/binning.h) against an independent double-precision
// reference: every output pixel of odd sizes, sizes not divisible by the factor, the camera
// sizes the CLI bins and the largest factor; its statuses on bad input; the factor chosen to fit
// and the coordinate mapping, worked by hand. The cross-target cases' checksums
// (platform/firmware/binning_cases.h, which the Cortex-M image checks on the target) are the
// reference's.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

#include "base/prng.h"
#include "binning_cases.h"
#include "gradient/binning.h"

using namespace qt;

namespace {

struct Frame {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;
    const uint8_t* row(int y) const { return pixels.data() + static_cast<size_t>(y) * width; }
};

// The reference: each output pixel the mean of its N × N block in double, rounded half up.
Frame reference_bin(const Frame& in, int n) {
    Frame out;
    out.width = in.width / n;
    out.height = in.height / n;
    out.pixels.resize(static_cast<size_t>(out.width) * out.height);
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            double sum = 0;
            for (int y = j * n; y < j * n + n; ++y)
                for (int x = i * n; x < i * n + n; ++x) sum += in.row(y)[x];
            const double mean = sum / (static_cast<double>(n) * n);
            out.pixels[static_cast<size_t>(j) * out.width + i] =
                static_cast<uint8_t>(std::floor(mean + 0.5));
        }
    return out;
}

// The stage, row by row; output rows checked to come in order, each once, of the right width.
Frame stage_bin(const Frame& in, int n) {
    static BinningStage<640> stage;
    Frame out;
    REQUIRE(stage.begin_frame(static_cast<uint16_t>(in.width), static_cast<uint16_t>(in.height),
                              static_cast<uint8_t>(n)) == Status::ok);
    out.width = stage.out_width();
    out.height = stage.out_height();
    int next = 0;
    for (int y = 0; y < in.height; ++y) {
        const Status s = stage.push_row(in.row(y), static_cast<uint16_t>(in.width),
                                        [&](uint16_t j, const uint8_t* row, uint16_t w) {
                                            CHECK(j == next);
                                            CHECK(w == out.width);
                                            out.pixels.insert(out.pixels.end(), row, row + w);
                                            ++next;
                                            return Status::ok;
                                        });
        REQUIRE(s == Status::ok);
    }
    CHECK(next == out.height);
    CHECK_FALSE(stage.in_frame());
    return out;
}

Frame case_frame(const BinningCase& c) {
    Frame f;
    f.width = c.width;
    f.height = c.height;
    f.pixels.resize(static_cast<size_t>(f.width) * f.height);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            f.pixels[static_cast<size_t>(y) * f.width + x] =
                binning_pixel(c.seed, c.mode, static_cast<uint32_t>(x), static_cast<uint32_t>(y));
    return f;
}

uint32_t checksum(const Frame& f) {
    uint32_t h = kFnvOffset;
    for (uint8_t p : f.pixels) h = fnv1a(h, p);
    return h;
}

}  // namespace

TEST_CASE("binning: every output pixel equals the double reference", "[binning]") {
    Pcg32 rng(20);
    // width, height, factor: odd sizes, sizes not divisible by the factor, factor 1, the largest
    // factor, a single output pixel, the full output width.
    const int sizes[][3] = {{1, 1, 1},       {7, 5, 1},     {7, 5, 2},     {333, 217, 2},
                            {333, 217, 3},   {100, 50, 3},  {641, 481, 2}, {1280, 720, 2},
                            {1921, 1081, 3}, {768, 576, 2}, {65, 47, 16},  {16, 16, 16},
                            {31, 17, 16},    {640, 3, 1},   {12, 12, 5},   {2559, 9, 4}};
    for (const auto& sz : sizes) {
        Frame in;
        in.width = sz[0];
        in.height = sz[1];
        in.pixels.resize(static_cast<size_t>(in.width) * in.height);
        for (int fill = 0; fill < 3; ++fill) {
            // Random grey levels; only 0 and 255 (the largest sums); levels 0 and 1 (ties: a
            // block mean of exactly k + 1/2 rounds up).
            for (uint8_t& p : in.pixels)
                p = fill == 0   ? static_cast<uint8_t>(rng.below(256))
                    : fill == 1 ? static_cast<uint8_t>(rng.below(2) * 255)
                                : static_cast<uint8_t>(rng.below(2));
            INFO(in.width << " x " << in.height << " by " << sz[2] << ", fill " << fill);
            const Frame want = reference_bin(in, sz[2]);
            const Frame got = stage_bin(in, sz[2]);
            REQUIRE(got.width == want.width);
            REQUIRE(got.height == want.height);
            CHECK(got.pixels == want.pixels);
        }
    }
}

TEST_CASE("binning: a tie rounds up, worked by hand", "[binning]") {
    // 6 × 2 by 2: blocks {0, 1, 0, 0} (mean 0.25 -> 0), {0, 1, 1, 0} (0.5, a tie -> 1) and
    // {255, 255, 255, 254} (254.75 -> 255).
    const uint8_t rows[2][6] = {{0, 1, 0, 1, 255, 255}, {0, 0, 1, 0, 255, 254}};
    BinningStage<640> stage;
    REQUIRE(stage.begin_frame(6, 2, 2) == Status::ok);
    std::vector<uint8_t> out;
    auto sink = [&](uint16_t, const uint8_t* row, uint16_t w) {
        out.assign(row, row + w);
        return Status::ok;
    };
    REQUIRE(stage.push_row(rows[0], 6, sink) == Status::ok);
    CHECK(out.empty());  // a block row is out only after its last input row
    REQUIRE(stage.push_row(rows[1], 6, sink) == Status::ok);
    CHECK(out == std::vector<uint8_t>{0, 1, 255});
}

TEST_CASE("binning: the cross-target cases' checksums are the reference's", "[binning]") {
    for (const BinningCase& c : kBinningCases) {
        INFO(c.name);
        const Frame in = case_frame(c);
        const Frame want = reference_bin(in, c.factor);
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08x", checksum(want));
        INFO("reference checksum " << hex);
        CHECK(checksum(want) == c.checksum);
        CHECK(stage_bin(in, c.factor).pixels == want.pixels);
    }
}

TEST_CASE("binning: statuses on bad input", "[binning]") {
    BinningStage<640> stage;
    auto sink = [](uint16_t, const uint8_t*, uint16_t) { return Status::ok; };
    const std::vector<uint8_t> row(2000, 7);
    CHECK(stage.begin_frame(0, 10, 2) == Status::bad_size);
    CHECK(stage.begin_frame(10, 0, 2) == Status::bad_size);
    CHECK(stage.begin_frame(10, 10, 0) == Status::bad_size);
    CHECK(stage.begin_frame(1000, 1000, kMaxBinFactor + 1) == Status::bad_size);
    CHECK(stage.begin_frame(1, 10, 2) == Status::bad_size);     // no whole block across
    CHECK(stage.begin_frame(10, 1, 2) == Status::bad_size);     // nor down
    CHECK(stage.begin_frame(1282, 10, 2) == Status::bad_size);  // 641 wide: over 640
    CHECK_FALSE(stage.in_frame());
    CHECK(stage.push_row(row.data(), 10, sink) == Status::not_in_frame);

    // A wrong row length abandons the frame.
    REQUIRE(stage.begin_frame(1281, 4, 2) == Status::ok);  // 640 wide: the last column dropped
    CHECK(stage.out_width() == 640);
    CHECK(stage.push_row(row.data(), 1280, sink) == Status::bad_row_length);
    CHECK_FALSE(stage.in_frame());
    CHECK(stage.push_row(row.data(), 1281, sink) == Status::not_in_frame);

    // Rows past the last: not_in_frame; a frame begun before the last row: reported.
    REQUIRE(stage.begin_frame(4, 3, 2) == Status::ok);
    for (int y = 0; y < 3; ++y) CHECK(stage.push_row(row.data(), 4, sink) == Status::ok);
    CHECK(stage.push_row(row.data(), 4, sink) == Status::not_in_frame);
    REQUIRE(stage.begin_frame(4, 4, 2) == Status::ok);
    CHECK(stage.push_row(row.data(), 4, sink) == Status::ok);
    CHECK(stage.begin_frame(4, 4, 2) == Status::previous_frame_incomplete);
    CHECK(stage.in_frame());

    // The sink's status comes back (this frame abandons the one above).
    REQUIRE(stage.begin_frame(2, 2, 2) == Status::previous_frame_incomplete);
    CHECK(stage.push_row(row.data(), 2, sink) == Status::ok);
    CHECK(stage.push_row(row.data(), 2, [](uint16_t, const uint8_t*, uint16_t) {
        return Status::capacity_exceeded;
    }) == Status::capacity_exceeded);
}

TEST_CASE("binning: the factor that fits and the coordinate mapping, worked by hand", "[binning]") {
    CHECK(bin_factor_to_fit(640, 480, 640, 480) == 1);
    CHECK(bin_factor_to_fit(641, 480, 640, 480) == 2);
    CHECK(bin_factor_to_fit(768, 576, 640, 480) == 2);
    CHECK(bin_factor_to_fit(1280, 720, 640, 480) == 2);
    CHECK(bin_factor_to_fit(1281, 961, 640, 480) == 2);  // 640 × 480: the odd pixels dropped
    CHECK(bin_factor_to_fit(1282, 720, 640, 480) == 3);  // 641 wide by 2
    CHECK(bin_factor_to_fit(1920, 1080, 640, 480) == 3);
    CHECK(bin_factor_to_fit(800, 600, 640, 480) == 2);
    CHECK(bin_factor_to_fit(1280, 960, 640, 480) == 2);
    CHECK(bin_factor_to_fit(2592, 1944, 640, 480) == 5);  // by 4: 648 × 486
    CHECK(bin_factor_to_fit(3840, 2160, 640, 480) == 6);
    CHECK(bin_factor_to_fit(10240, 100, 640, 480) == 16);
    CHECK(bin_factor_to_fit(10255, 100, 640, 480) == 16);  // 640.9: the last 15 columns dropped
    CHECK(bin_factor_to_fit(10256, 100, 640, 480) == 0);   // 641 wide even by 16
    CHECK(bin_factor_to_fit(0, 100, 640, 480) == 0);
    CHECK(bin_factor_to_fit(2000, 3, 640, 480) == 0);  // too wide until 4, which leaves no row

    // Output pixel u covers input pixels N·u .. N·u + N − 1, whose centre is N·u + (N − 1)/2.
    CHECK(unbinned(q16_16::from_int(0), 1) == q16_16::from_int(0));
    CHECK(unbinned(q16_16::from_int(7), 1) == q16_16::from_int(7));
    CHECK(unbinned(q16_16::from_int(0), 2) == q16_16::from_ratio(1, 2));
    CHECK(unbinned(q16_16::from_int(10), 2) == q16_16::from_ratio(41, 2));
    CHECK(unbinned(q16_16::from_int(10), 3) == q16_16::from_int(31));
    CHECK(unbinned(q16_16::from_ratio(-1, 2), 3) == q16_16::from_ratio(-1, 2));
    CHECK(unbinned(q16_16::from_int(30000), 16).raw == INT32_MAX);  // saturated
}

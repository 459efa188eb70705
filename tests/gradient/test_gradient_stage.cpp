// The streaming core gradient stage against a whole-frame reference, and its error statuses.
#include <catch2/catch.hpp>
#include <vector>

#include "base/prng.h"
#include "gradient/gradient_stage.h"
#include "support/spec_reference.h"

using namespace qt;

namespace {

struct Collected {
    std::vector<gradient_word> words;
    std::vector<int> row_order;
};

template <class Stage>
Status run_frame(Stage& stage, const std::vector<uint8_t>& px, int w, int h, Collected& c) {
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t width) {
        c.row_order.push_back(y);
        REQUIRE(width == w);
        c.words.insert(c.words.end(), words, words + width);
    };
    Status s = stage.begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
    for (int y = 0; y < h && s == Status::ok; ++y)
        s = stage.push_row(px.data() + static_cast<size_t>(y) * w, static_cast<uint16_t>(w), sink);
    return s;
}

void require_equal_to_reference(const std::vector<uint8_t>& px, int w, int h, const Collected& c) {
    const auto ref = ref::frame_gradients(px, w, h);
    REQUIRE(c.words.size() == ref.size());
    for (int y = 0; y < h; ++y) REQUIRE(c.row_order[static_cast<size_t>(y)] == y);
    for (size_t i = 0; i < ref.size(); ++i) {
        INFO("frame " << w << "x" << h << " pixel " << i % static_cast<size_t>(w) << ","
                      << i / static_cast<size_t>(w));
        REQUIRE(gradient_gx(c.words[i]) == ref[i].gx);
        REQUIRE(gradient_gy(c.words[i]) == ref[i].gy);
        REQUIRE(gradient_mag(c.words[i]) == static_cast<uint32_t>(ref[i].mag));
        REQUIRE(gradient_dir(c.words[i]) == ref[i].dir);
    }
}

std::vector<uint8_t> noise(int w, int h, Pcg32& rng) {
    std::vector<uint8_t> px(static_cast<size_t>(w) * h);
    for (uint8_t& p : px) p = static_cast<uint8_t>(rng.next());
    return px;
}

}  // namespace

TEST_CASE("gradient stage equals the whole-frame reference at many sizes", "[gradient]") {
    static GradientStage<640> stage;
    Pcg32 rng(8);
    const int sizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {3, 3}, {37, 23}, {640, 4}, {640, 1}};
    for (const auto& wh : sizes) {
        const auto px = noise(wh[0], wh[1], rng);
        Collected c;
        REQUIRE(run_frame(stage, px, wh[0], wh[1], c) == Status::ok);
        require_equal_to_reference(px, wh[0], wh[1], c);
        REQUIRE_FALSE(stage.in_frame());
    }
    for (int i = 0; i < 40; ++i) {  // random sizes, frames back to back through one stage
        const int w = 1 + static_cast<int>(rng.below(640)), h = 1 + static_cast<int>(rng.below(12));
        const auto px = noise(w, h, rng);
        Collected c;
        REQUIRE(run_frame(stage, px, w, h, c) == Status::ok);
        require_equal_to_reference(px, w, h, c);
    }
}

TEST_CASE("gx/gy-only words equal the reference's gx and gy, magnitude and direction 0",
          "[gradient]") {
    static GradientStage<640, XyWordRowKernel> stage;
    Pcg32 rng(9);
    const int sizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {3, 3}, {37, 23}, {640, 4}, {320, 7}};
    for (const auto& wh : sizes) {
        const int w = wh[0], h = wh[1];
        const auto px = noise(w, h, rng);
        Collected c;
        REQUIRE(run_frame(stage, px, w, h, c) == Status::ok);
        const auto ref = ref::frame_gradients(px, w, h);
        REQUIRE(c.words.size() == ref.size());
        for (size_t i = 0; i < ref.size(); ++i) {
            INFO("frame " << w << "x" << h << " pixel " << i);
            REQUIRE(gradient_gx(c.words[i]) == ref[i].gx);
            REQUIRE(gradient_gy(c.words[i]) == ref[i].gy);
            REQUIRE(gradient_mag(c.words[i]) == 0u);
            REQUIRE(gradient_dir(c.words[i]) == 0u);
        }
    }
}

TEST_CASE("gradient stage reports bad sizes, wrong rows and torn frames, then recovers",
          "[gradient]") {
    static GradientStage<64> stage;
    auto ignore = [](uint16_t, const gradient_word*, uint16_t) {};
    const std::vector<uint8_t> row(65, 100);
    REQUIRE(stage.begin_frame(0, 10) == Status::bad_size);
    REQUIRE(stage.begin_frame(10, 0) == Status::bad_size);
    REQUIRE(stage.begin_frame(65, 10) == Status::bad_size);
    REQUIRE(stage.push_row(row.data(), 10, ignore) == Status::not_in_frame);

    REQUIRE(stage.begin_frame(10, 3) == Status::ok);
    REQUIRE(stage.push_row(row.data(), 10, ignore) == Status::ok);
    REQUIRE(stage.push_row(row.data(), 9, ignore) == Status::bad_row_length);
    REQUIRE(stage.push_row(row.data(), 10, ignore) == Status::not_in_frame);  // frame abandoned

    REQUIRE(stage.begin_frame(10, 3) == Status::ok);
    REQUIRE(stage.push_row(row.data(), 10, ignore) == Status::ok);
    REQUIRE(stage.begin_frame(8, 2) == Status::previous_frame_incomplete);  // ended early

    // The next frame after all of that is processed normally.
    Pcg32 rng(9);
    const auto px = noise(8, 2, rng);
    Collected c;
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t width) {
        c.row_order.push_back(y);
        c.words.insert(c.words.end(), words, words + width);
    };
    REQUIRE(stage.push_row(px.data(), 8, sink) == Status::ok);
    REQUIRE(stage.push_row(px.data() + 8, 8, sink) == Status::ok);
    require_equal_to_reference(px, 8, 2, c);
    REQUIRE(stage.push_row(px.data(), 8, sink) == Status::not_in_frame);  // past the last row
}

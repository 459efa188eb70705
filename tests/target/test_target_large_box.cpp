// Targets larger than the template (TargetPipeline::set_target at a step above 1): a textured
// box of 72 x 52 px moving over a static textured background, against the rendered positions;
// the sizes set_target takes and refuses.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "demo/target_runner.h"
#include "target/float/target_pipeline.h"

namespace {

constexpr int kW = 320, kH = 240;
constexpr int kBoxW = 72, kBoxH = 52;  // blocks of 5 px: 15 x 11 (72 > 16 · 4)

// Smooth textures (grey levels) of the background and of the target, different enough that
// the target's template never matches the background.
double background(int x, int y) {
    return 110 + 40 * std::sin(0.21 * x + 0.05 * y) + 30 * std::sin(-0.07 * x + 0.17 * y + 1.0);
}
double target_texture(int x, int y) {  // x, y from the target's top-left
    return 140 + 50 * std::sin(0.35 * x + 0.9) * std::cos(0.28 * y) +
           30 * std::sin(0.11 * x - 0.23 * y + 2.0);
}

qt::io::GreyImage frame(int tx, int ty) {
    qt::io::GreyImage img(kW, kH, 0);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const bool in = x >= tx && x < tx + kBoxW && y >= ty && y < ty + kBoxH;
            const double v = in ? target_texture(x - tx, y - ty) : background(x, y);
            img.at(x, y) = static_cast<uint8_t>(std::lround(v < 0 ? 0 : v > 255 ? 255 : v));
        }
    return img;
}

}  // namespace

TEST_CASE("target pipeline: a 72 x 52 px target tracked in blocks of 5 px", "[target][large]") {
    static qt::TargetPipelineQvga pipeline;
    const qt::TargetPipelineParams params = qt::cli::qvga_target_config(qt::TargetMethod::fused);
    const int x0 = 60, y0 = 70, vx = 3, vy = 1;  // px, px per frame
    REQUIRE(pipeline.set_target(x0, y0, kBoxW, kBoxH) == qt::Status::ok);
    double worst = 0;
    int measured = 0;
    for (int k = 0; k < 30; ++k) {
        const int tx = x0 + vx * k, ty = y0 + vy * k;
        const qt::io::GreyImage img = frame(tx, ty);
        REQUIRE(pipeline.begin_frame(kW, kH, params) == qt::Status::ok);
        for (int y = 0; y < kH; ++y) REQUIRE(pipeline.push_row(img.row(y), kW) == qt::Status::ok);
        qt::TargetFrame out;
        const qt::Status s = pipeline.finish(out);
        REQUIRE((s == qt::Status::ok || s == qt::Status::capacity_exceeded));
        REQUIRE(out.tracking);
        // The truth: the box's centre, as set_target() defines it.
        const double cx = tx + 0.5 * (kBoxW - 1), cy = ty + 0.5 * (kBoxH - 1);
        const double e = std::hypot(out.estimate.x - cx, out.estimate.y - cy);
        INFO("frame " << k << ": estimate (" << out.estimate.x << ", " << out.estimate.y
                      << "), truth (" << cx << ", " << cy << "), state "
                      << qt::target_state_name(out.estimate.state));
        CHECK(e < 1.25);  // a quarter of a block (1.06 px measured, frame 5: the velocity settles)
        worst = std::max(worst, e);
        if (k > 0) {
            CHECK(out.estimate.state == qt::TargetState::measured);
            // The window and the hit are in frame pixels, not blocks.
            CHECK(std::abs(out.window.x - cx) < 8);
            CHECK(std::abs(out.hit.x_q8 / 256.0 - cx) < 3);
            measured += out.estimate.state == qt::TargetState::measured;
        }
    }
    WARN("72 x 52 px target over 30 frames: worst error " << worst << " px, " << measured
                                                          << " of 29 frames measured");
}

TEST_CASE("set_target: boxes up to MaxTemplate blocks of up to 16 px a side", "[target][large]") {
    static qt::TargetPipelineQvga p;
    constexpr uint32_t largest = qt::TargetPipelineQvga::max_box_side();
    STATIC_REQUIRE(largest == 16 * 16);  // 16 blocks of 16 px: the grid starts on the box
    CHECK(p.set_target(0, 0, 0, 5) == qt::Status::bad_size);
    CHECK(p.set_target(0, 0, 5, 0) == qt::Status::bad_size);
    for (int32_t x = -20; x < 20; ++x) {
        CHECK(p.set_target(x, 3, largest, 16) == qt::Status::ok);
        CHECK(p.set_target(x, 3, 16, largest) == qt::Status::ok);
        CHECK(p.set_target(x, 3, largest + 1, 5) == qt::Status::bad_size);
        CHECK(p.set_target(x, 3, 5, largest + 1) == qt::Status::bad_size);
    }
}

TEST_CASE(
    "target pipeline: a 40 x 40 px bright square tracked by the morphological detector in "
    "blocks of 3 px",
    "[target][large]") {
    static qt::TargetPipelineQvga pipeline;
    qt::TargetPipelineParams params = qt::cli::qvga_target_config(qt::TargetMethod::fused);
    params.detector = qt::TargetDetector::morphological;
    const int side = 40, x0 = 80, y0 = 90, vx = 2, vy = 1;  // blocks of 3 px: 14 x 14
    REQUIRE(pipeline.set_target(x0, y0, side, side) == qt::Status::ok);
    double worst = 0;
    for (int k = 0; k < 20; ++k) {
        const int tx = x0 + vx * k, ty = y0 + vy * k;
        qt::io::GreyImage img(kW, kH, 0);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const bool in = x >= tx && x < tx + side && y >= ty && y < ty + side;
                img.at(x, y) = static_cast<uint8_t>(
                    in ? 220 : std::lround(std::min(120.0, std::max(0.0, background(x, y) - 40))));
            }
        REQUIRE(pipeline.begin_frame(kW, kH, params) == qt::Status::ok);
        for (int y = 0; y < kH; ++y) REQUIRE(pipeline.push_row(img.row(y), kW) == qt::Status::ok);
        qt::TargetFrame out;
        const qt::Status s = pipeline.finish(out);
        REQUIRE((s == qt::Status::ok || s == qt::Status::capacity_exceeded));
        const double cx = tx + 0.5 * (side - 1), cy = ty + 0.5 * (side - 1);
        const double e = std::hypot(out.estimate.x - cx, out.estimate.y - cy);
        INFO("frame " << k << ": estimate (" << out.estimate.x << ", " << out.estimate.y
                      << "), truth (" << cx << ", " << cy << "), state "
                      << qt::target_state_name(out.estimate.state));
        if (k > 0) CHECK(out.estimate.state == qt::TargetState::measured);
        CHECK(e < 3.0);  // a block: the cluster's centroid on block means (2.28 px measured)
        worst = std::max(worst, e);
    }
    WARN("40 x 40 px bright square, morphological detector: worst error " << worst << " px");
}

// Corner accuracy of the whole detection chain against the ground truth of generated board scenes
// (platform/scene/board_bench_scene.h), on seeds the defaults were not tuned on (the bench uses
// 1000000+). The full-size table with the OpenCV baseline is `bash bench.sh quads-host`.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "scene/board_bench_scene.h"

using namespace qt;

namespace {

BoardDetectorQvga g_det;

uint16_t detect(const io::GreyImage& img) {
    const Status s = io::push_frame(g_det, img, BoardParams{});
    REQUIRE((s == Status::ok || s == Status::capacity_exceeded));
    return g_det.quad_count();
}

}  // namespace

TEST_CASE("boards under perspective: found, corners within half a pixel RMS",
          "[quad_scenes][slow]") {
    const int kScenes = 40;
    int found = 0, corners = 0;
    double sum_sq = 0, worst = 0;
    for (int k = 0; k < kScenes; ++k) {
        const scene::BoardBenchScene s =
            scene::make_board_bench_scene(scene::BoardBenchOptions{}, 5000u + k);
        if (detect(s.image) == 0) continue;
        double scene_worst = 0, scene_sq = 0;
        for (int i = 0; i < 4; ++i) {
            const Point16 c = g_det.quads()[0].corners[i];
            const double e =
                std::hypot(c.x.raw / 65536.0 - s.corners[i].x, c.y.raw / 65536.0 - s.corners[i].y);
            scene_worst = std::fmax(scene_worst, e);
            scene_sq += e * e;
        }
        if (scene_worst > 3) continue;  // another quadrangle: not the board
        ++found;
        sum_sq += scene_sq;
        corners += 4;
        worst = std::fmax(worst, scene_worst);
    }
    INFO("found " << found << " of " << kScenes << ", worst corner " << worst << " px");
    CHECK(found >= kScenes - 1);
    REQUIRE(corners > 0);
    CHECK(std::sqrt(sum_sq / corners) <= 0.5);
}

TEST_CASE("board-free cluttered frames give no quadrangle", "[quad_scenes][slow]") {
    scene::BoardBenchOptions o;
    o.board = false;
    int false_detections = 0;
    for (int k = 0; k < 40; ++k)
        if (detect(scene::make_board_bench_scene(o, 6000u + k).image) > 0) ++false_detections;
    CHECK(false_detections == 0);
}

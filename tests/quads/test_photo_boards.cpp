// The board in front of real backgrounds: clutter that fills every capacity of the chain does
// not cost a board that is the most salient quadrangle in the frame, and boards composited
// onto real photographs (Debian's opencv-doc samples, platform/scene/photo_board_scene.h) are found
// with sub-pixel corners while board-free frames rarely give a quadrangle. The full table is
// `bash bench.sh photos-host`; these seeds (7000000+) are not the bench's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "scene/det_math.h"
#include "scene/line_scene.h"
#include "scene/photo_board_scene.h"
#include "scene/random.h"

using namespace qt;

namespace {

BoardDetectorQvga g_qvga;
BoardDetectorVga g_vga;

// Worst corner error of the best quadrangle against the truth, px (1e9 when none).
template <class Detector>
double worst_corner(Detector& det, const io::GreyImage& img, const scene::Point2 truth[4],
                    double* sq = nullptr, const BoardParams& params = BoardParams{}) {
    const Status s = io::push_frame(det, img, params);
    REQUIRE((s == Status::ok || s == Status::capacity_exceeded));
    if (det.quad_count() == 0) return 1e9;
    double worst = 0;
    for (int i = 0; i < 4; ++i) {
        const Point16 c = det.quads()[0].corners[i];
        const double e = std::hypot(c.x.raw / 65536.0 - truth[i].x, c.y.raw / 65536.0 - truth[i].y);
        worst = std::fmax(worst, e);
        if (sq) *sq += e * e;
    }
    return worst;
}

const std::vector<io::NamedImage>& photos() {
    static std::vector<io::NamedImage> loaded;
    static std::string error;
    if (loaded.empty() && error.empty() && !io::read_image_folder(QT_PHOTO_DIR, loaded, error) &&
        error.empty())
        error = "no photographs";
    INFO(error << (std::string(QT_PHOTOS_MISSING).empty() ? "" : "; missing: " QT_PHOTOS_MISSING));
    REQUIRE(std::string(QT_PHOTOS_MISSING).empty());
    REQUIRE(!loaded.empty());
    return loaded;
}

// Scene k of the photo bench's unoccluded set (bash bench.sh photos-host: its seed and
// photograph) at width × height.
scene::PhotoBoardScene unoccluded_bench_scene(int k, int width, int height) {
    scene::PhotoBoardOptions o;
    o.width = width;
    o.height = height;
    const auto& photo = photos()[static_cast<size_t>(k) % photos().size()].image;
    return scene::make_photo_board_scene(o, photo, 1000000 + static_cast<uint64_t>(k));
}

struct Tally {
    int scenes = 0, detected = 0, quads = 0, corners = 0;
    double sum_sq = 0;
};

// `scenes` scenes, the photographs in turn (only those named in `only` when it is not empty).
template <class Detector>
Tally run_set(Detector& det, int width, int height, bool board, bool occlude, uint64_t seed0,
              int scenes, const std::vector<std::string>& only = {}) {
    std::vector<const io::GreyImage*> chosen;
    for (const io::NamedImage& p : photos())
        if (only.empty() || std::find(only.begin(), only.end(), p.name) != only.end())
            chosen.push_back(&p.image);
    REQUIRE(!chosen.empty());
    Tally t;
    for (int k = 0; k < scenes; ++k) {
        scene::PhotoBoardOptions o;
        o.width = width;
        o.height = height;
        o.board = board;
        o.occlude = occlude;
        const auto& photo = *chosen[static_cast<size_t>(k) % chosen.size()];
        const scene::PhotoBoardScene s =
            scene::make_photo_board_scene(o, photo, seed0 + static_cast<uint64_t>(k));
        double sq = 0;
        const double worst = worst_corner(det, s.image, s.corners, &sq);
        ++t.scenes;
        t.quads += det.quad_count() > 0;
        if (board && worst <= 3) {
            ++t.detected;
            t.sum_sq += sq;
            t.corners += 4;
        }
    }
    return t;
}

}  // namespace

TEST_CASE("clutter that fills every capacity does not cost the most salient board",
          "[photo_boards]") {
    // A facade of bars: 6 a row, 26 rows, each bar 40 × 3 px of grey 70–130 on grey 40 and
    // turned up to ±8°: 312 bars, two long edges each, fill the edge list and the segment list
    // many times over. The board (grey 230) lies in the bottom half, whose edges and lines
    // come last in raster and PPHT order.
    scene::SceneOptions o;
    o.background = 40;
    o.blur_sigma = 0.7;
    o.noise_sigma = 3;
    scene::LineScene ls(o);
    Pcg32 rng(77);
    for (int k = 0; k < 312; ++k) {
        const double x = 6 + (k % 6) * 52, y = 6 + (k / 6) * 9.0;
        double st, ct;  // the scenes' own sine and cosine: the same bars on every platform
        scene::det_sincos(scene::uniform(rng, -0.14, 0.14), st, ct);
        const scene::Point2 a{x, y}, b{x + 40 * ct, y + 40 * st};
        ls.add_line(a, b, 3, static_cast<uint8_t>(scene::uniform_int(rng, 70, 130)));
    }
    const scene::Point2 board[4] = {{90.4, 120.6}, {98.1, 226.2}, {240.7, 219.5}, {231.2, 115.3}};
    ls.add_polygon({board, board + 4}, 230);
    const io::GreyImage img = ls.render();

    CHECK(worst_corner(g_qvga, img, board) < 1.0);
    const LineStats& s = g_qvga.lines().stats();
    CHECK(s.edges_dropped > 0);                  // the edge list filled ...
    CHECK(g_qvga.lines().edges().floor() > 40);  // ... and raised its floor
    WARN("edges dropped " << s.edges_dropped << ", segments dropped " << s.hough.segments_dropped
                          << ", clusters dropped " << s.cluster.clusters_dropped);
    CHECK(s.hough.segments_dropped > 0);    // the segment list filled too
    CHECK(s.cluster.clusters_dropped > 0);  // and the line list
}

TEST_CASE("boards whose sides are weaker than the photograph's edges keep them in a full list",
          "[photo_boards]") {
    // Scenes of the photo bench (bash bench.sh photos-host, unoccluded QVGA set, its seeds and
    // photographs) in which the board's weakest side is fainter than the facade's or the
    // painting's edges: a list that kept only its strongest edges lost at least one side in
    // each (the bench at commit 887dedd listed them as missed). Thinned, every other step of
    // the faint sides stays (lines/edge_list.h).
    for (const int k : {84, 108, 176, 584, 608, 1352}) {
        const scene::PhotoBoardScene s = unoccluded_bench_scene(k, 320, 240);
        INFO("scene " << k);
        CHECK(worst_corner(g_qvga, s.image, s.corners) <= 3);
        CHECK(g_qvga.lines().edges().thin_level() > g_qvga.lines().edges().floor());
    }
}

TEST_CASE("a square board tilted past rule 5's tolerance is found by its converging sides",
          "[photo_boards]") {
    // Scenes of the photo bench (VGA unoccluded set, its seeds and photographs): 1:1 boards
    // tilted 34.5° (apple) and 29.2° (squirrel_cls) that read beyond 1.8 off the 4:3 display,
    // which rule 5 turned down before the allowance for converging sides (quad_rules.h).
    BoardParams no_allowance;
    no_allowance.quads.perspective_convergence = kAngleQuarterTurn + 1;  // never reached
    for (const int k : {963, 1389}) {
        const scene::PhotoBoardScene s = unoccluded_bench_scene(k, 640, 480);
        INFO("scene " << k);
        CHECK(worst_corner(g_vga, s.image, s.corners) <= 3);
        CHECK(worst_corner(g_vga, s.image, s.corners, nullptr, no_allowance) > 3);
    }
}

TEST_CASE("boards on real photographs: found with sub-pixel corners, false detections rare",
          "[photo_boards][slow]") {
    // Regression guards at the measured level (bash bench.sh photos-host gives the full
    // figures and says where the aims are not met).
    const Tally u = run_set(g_qvga, 320, 240, true, false, 7000000, 48);
    WARN("QVGA unoccluded: " << u.detected << " of " << u.scenes);
    CHECK(u.detected >= 47);
    REQUIRE(u.corners > 0);
    CHECK(std::sqrt(u.sum_sq / u.corners) <= 0.3);

    const Tally occ = run_set(g_qvga, 320, 240, true, true, 7100000, 24);
    WARN("QVGA occluded: " << occ.detected << " of " << occ.scenes);
    CHECK(occ.detected >= 23);

    const Tally none = run_set(g_qvga, 320, 240, false, false, 7200000, 48);
    WARN("QVGA board-free frames with a quadrangle: " << none.quads << " of " << none.scenes);
    CHECK(none.quads <= 1);

    const Tally v = run_set(g_vga, 640, 480, true, false, 7300000, 16);
    WARN("VGA unoccluded: " << v.detected << " of " << v.scenes);
    CHECK(v.detected >= 16);
    REQUIRE(v.corners > 0);
    CHECK(std::sqrt(v.sum_sq / v.corners) <= 0.3);
}

TEST_CASE("a photograph's own printed rectangles are not taken for the board", "[photo_boards]") {
    // left.pnm holds a box whose printed face is a clean quadrangle, box_in_scene.pnm boxes and
    // books: the outline passes every rule, the print inside does not (quad_interior.h). Without
    // the inside test 5 of these 48 frames gave a quadrangle; with it, 1.
    const Tally none =
        run_set(g_qvga, 320, 240, false, false, 7400000, 48, {"left.pnm", "box_in_scene.pnm"});
    WARN("QVGA board-free frames of boxes with a quadrangle: " << none.quads << " of "
                                                               << none.scenes);
    CHECK(none.quads <= 1);
}

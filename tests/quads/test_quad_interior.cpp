// The inside of a quadrangle (quad_interior.h): cells holding edge points counted against a
// square worked by hand, the limit's arithmetic by hand, and the detector keeping a blank board
// while it turns down a printed rectangle of the same outline.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "quads/quad_interior.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

Point16 corner(int32_t x, int32_t y) { return {q16_16::from_int(x), q16_16::from_int(y)}; }

// Points of a 64-row list, pushed row by row in increasing x.
struct Points {
    EdgeListStorage<64, 64> storage;
    EdgeList list = storage.view();
    explicit Points(std::vector<std::pair<uint16_t, uint16_t>> xy) {
        REQUIRE(list.begin_frame(64) == Status::ok);
        std::sort(xy.begin(), xy.end(), [](auto a, auto b) {
            return a.second != b.second ? a.second < b.second : a.first < b.first;
        });
        int32_t row = -1;
        for (auto [x, y] : xy) {
            if (y != row) list.begin_row(y), row = y;
            REQUIRE(list.push(x, 0, 0, 100));
        }
        list.end_frame();
    }
};

}  // namespace

TEST_CASE("cells inside a square holding edge points, farther than the margin from its sides",
          "[interior]") {
    // The square (10, 10)–(50, 50): 1600 px². With a margin of 4 px a point counts when
    // 14 < x < 46 and 14 < y < 46 (strictly: 4 px from a side is on the margin); its cell is
    // (x / 2, y / 2).
    const Points p({{30, 30},    // middle: in, cell (15, 15)
                    {31, 31},    // in, the same cell
                    {15, 30},    // 5 px from the left side: in, cell (7, 15)
                    {45, 45},    // 5 px from the right and the bottom: in, cell (22, 22)
                    {14, 30},    // 4 px from the left: out (cell (7, 15) all the same)
                    {30, 46},    // 4 px from the bottom: out, cell (15, 23)
                    {12, 12},    // near a corner: out, cell (6, 6)
                    {5, 30},     // left of the square: out
                    {55, 30},    // right of it: out
                    {30, 60}});  // below it: out
    const Point16 acw[4] = {corner(10, 10), corner(10, 50), corner(50, 50), corner(50, 10)};
    const InteriorCount c = count_inside_edges(p.list, acw, q16_16::from_int(4));
    CHECK(c.cells == 3);
    CHECK(c.area_px == 1600);
    // Either winding.
    const Point16 cw[4] = {acw[0], acw[3], acw[2], acw[1]};
    CHECK(count_inside_edges(p.list, cw, q16_16::from_int(4)).cells == 3);
    // No margin: every point strictly inside counts, in 5 cells.
    CHECK(count_inside_edges(p.list, acw, q16_16::from_int(0)).cells == 5);
}

TEST_CASE("a turned quadrangle: the margin is measured across each side", "[interior]") {
    // A diamond about (32, 32) with its corners 20 px out: sides at 45°, the centre 20/√2 =
    // 14.1 px from each; the upper sides lie on x + y = 44 and x − y = 20.
    const Point16 d[4] = {corner(32, 12), corner(12, 32), corner(32, 52), corner(52, 32)};
    // (32, 32): 14.1 px from every side; (32, 20): 8/√2 = 5.66 px from the two upper sides;
    // (32, 18): 6/√2 = 4.24 px; (32, 17): 5/√2 = 3.54 px. Each in a cell of its own.
    const Points p({{32, 32}, {32, 20}, {32, 18}, {32, 17}});
    CHECK(count_inside_edges(p.list, d, q16_16::from_int(4)).cells == 3);
    CHECK(count_inside_edges(p.list, d, q16_16::from_int(5)).cells == 2);
    CHECK(count_inside_edges(p.list, d, q16_16::from_int(6)).cells == 1);
    CHECK(count_inside_edges(p.list, d, q16_16::from_int(4)).area_px == 800);
}

TEST_CASE("the limit on the share of cells scales with the root of the frame's rows",
          "[interior]") {
    // 16 % of the 400 cells of 1600 px² at 240 rows: 64; at 480 rows 64 / √2 = 45.25; at 60
    // rows 64 · 2 = 128.
    CHECK(interior_clear({64, 1600}, 240, 16));
    CHECK(!interior_clear({65, 1600}, 240, 16));
    CHECK(interior_clear({45, 1600}, 480, 16));
    CHECK(!interior_clear({46, 1600}, 480, 16));
    CHECK(interior_clear({128, 1600}, 60, 16));
    CHECK(!interior_clear({129, 1600}, 60, 16));
    CHECK(interior_clear({400, 1600}, 240, 0));  // 0: not tested
    CHECK(interior_clear({0, 0}, 240, 16));
}

namespace {

BoardDetectorQvga g_det;

// A bright quadrangle of the given outline on a dark background, blank or printed: inside it
// rows of dark "words" (bars 12 × 4 px at grey 90, 5 px apart, a row every 8 px), a box's
// printed face.
io::GreyImage quad_frame(const std::vector<scene::Point2>& outline, bool printed) {
    scene::SceneOptions o;
    o.background = 50;
    o.blur_sigma = 0.7;
    o.noise_sigma = 2;
    o.seed = 3;
    scene::LineScene ls(o);
    ls.add_polygon(outline, 220);
    if (printed)
        for (double y = 80; y < 160; y += 8)
            for (double x = 115; x + 12 < 210; x += 17)
                ls.add_polygon({{x, y}, {x + 12, y}, {x + 12, y + 4}, {x, y + 4}}, 90);
    return ls.render();
}

}  // namespace

TEST_CASE("a blank board is kept, a printed rectangle of the same outline is not", "[interior]") {
    const std::vector<scene::Point2> outline = {{90, 60}, {95, 185}, {235, 178}, {228, 55}};
    BoardParams params;
    REQUIRE(io::push_frame(g_det, quad_frame(outline, false), params) == Status::ok);
    REQUIRE(g_det.quad_count() >= 1);
    CHECK(g_det.quad_stats().rejected_interior == 0);

    const Status s = io::push_frame(g_det, quad_frame(outline, true), params);
    REQUIRE((s == Status::ok || s == Status::capacity_exceeded));
    CHECK(g_det.quad_count() == 0);
    CHECK(g_det.quad_stats().rejected_interior >= 1);

    // With the test off the printed rectangle is a quadrangle like any other.
    params.refine.max_inside_edge_cells_percent = 0;
    REQUIRE(io::push_frame(g_det, quad_frame(outline, true), params) == s);
    REQUIRE(g_det.quad_count() >= 1);
    for (int i = 0; i < 4; ++i) {
        const Point16 c = g_det.quads()[0].corners[i];
        bool near = false;
        for (const scene::Point2& t : outline)
            near = near || std::hypot(c.x.raw / 65536.0 - t.x, c.y.raw / 65536.0 - t.y) < 2;
        CHECK(near);
    }
}

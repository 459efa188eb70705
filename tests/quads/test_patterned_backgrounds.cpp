// Patterned backgrounds: corners that are crossings (quad_refine.h, junction_corners) and
// verification in rank order past the candidates that fail (board_detector.h), against
// geometry laid out by hand.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "quads/quad_refine.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

Point16 corner(int32_t x, int32_t y) { return {q16_16::from_int(x), q16_16::from_int(y)}; }

// An edge list of 96 rows holding the given horizontal runs (y, x0..x1; gradient along y,
// direction bin 4) and vertical runs (x, y0..y1; gradient along x, bin 0).
struct Runs {
    EdgeListStorage<2048, 96> storage;
    EdgeList list = storage.view();
    Runs(const std::vector<std::array<int, 3>>& rows, const std::vector<std::array<int, 3>>& cols) {
        std::vector<std::array<uint32_t, 3>> points;  // y, x, dir
        for (const auto& r : rows)
            for (int x = r[1]; x <= r[2]; ++x)
                points.push_back({static_cast<uint32_t>(r[0]), static_cast<uint32_t>(x), 4});
        for (const auto& c : cols)
            for (int y = c[1]; y <= c[2]; ++y)
                points.push_back({static_cast<uint32_t>(y), static_cast<uint32_t>(c[0]), 0});
        std::sort(points.begin(), points.end());
        points.erase(std::unique(points.begin(), points.end(),
                                 [](auto a, auto b) { return a[0] == b[0] && a[1] == b[1]; }),
                     points.end());
        REQUIRE(list.begin_frame(96) == Status::ok);
        int32_t row = -1;
        for (const auto& p : points) {
            if (static_cast<int32_t>(p[0]) != row) list.begin_row(static_cast<uint16_t>(p[0]));
            row = static_cast<int32_t>(p[0]);
            REQUIRE(list.push(static_cast<uint16_t>(p[1]), p[2], 0, 100));
        }
        list.end_frame();
    }
};

}  // namespace

TEST_CASE("corners that are crossings: both sides run on past them", "[patterned]") {
    // The square (30, 30)–(60, 60): sides 30 px, so each side is looked at past a corner over
    // max(30 / 4, 6) = 7.5 px, beyond end_margin (3 px): from 3 to 10.5 px out.
    const Point16 sq[4] = {corner(30, 30), corner(30, 60), corner(60, 60), corner(60, 30)};
    const RefineParams p;
    // Its own outline only: no corner is a crossing.
    const Runs outline({{30, 30, 60}, {60, 30, 60}}, {{30, 30, 60}, {60, 30, 60}});
    CHECK(junction_corners(outline.list, sq, p) == 0);
    // A grid: lines x = 30, 60 and y = 30, 60 right across the frame: four crossings.
    const Runs grid({{30, 0, 90}, {60, 0, 90}}, {{30, 0, 90}, {60, 0, 90}});
    CHECK(junction_corners(grid.list, sq, p) == 4);
    // Either winding.
    const Point16 cw[4] = {sq[0], sq[3], sq[2], sq[1]};
    CHECK(junction_corners(grid.list, cw, p) == 4);
    // The top side runs on past both top corners, the left side past the top-left one: one
    // crossing (top-left); at the top-right the right side stops.
    const Runs tee({{30, 0, 90}, {60, 30, 60}}, {{30, 0, 60}, {60, 30, 60}});
    CHECK(junction_corners(tee.list, sq, p) == 1);
    // Runs on too short to count: 5 px past each corner cover 3 of the 8 steps from 3 to
    // 10.5 px out (under half); 8 px cover 6 of them.
    const Runs short_grid({{30, 25, 65}, {60, 25, 65}}, {{30, 25, 65}, {60, 25, 65}});
    CHECK(junction_corners(short_grid.list, sq, p) == 0);
    const Runs longer_grid({{30, 22, 68}, {60, 22, 68}}, {{30, 22, 68}, {60, 22, 68}});
    CHECK(junction_corners(longer_grid.list, sq, p) == 4);
}

namespace {

BoardDetectorQvga g_det;

// Verification of the 4 best candidates only, as before the candidates outnumbered the kept.
struct FourCandidates : Qvga {
    static constexpr uint16_t quad_candidates = 4;
};
BoardDetector<FourCandidates> g_four;

// Whether some reported quadrangle has every corner within 2 px of the outline's.
template <class Detector>
bool found(const Detector& det, const std::vector<scene::Point2>& outline) {
    for (uint16_t q = 0; q < det.quad_count(); ++q) {
        bool all = true;
        for (int i = 0; i < 4; ++i) {
            bool near = false;
            for (const scene::Point2& t : outline)
                near = near || std::hypot(det.quads()[q].corners[i].x.raw / 65536.0 - t.x,
                                          det.quads()[q].corners[i].y.raw / 65536.0 - t.y) < 2;
            all = all && near;
        }
        if (all) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("the board is verified past better-ranked candidates that fail", "[patterned]") {
    // Four printed cards (bright, rows of dark bars inside: the blank-inside test turns them
    // down) and a blank board, smaller: all five are whole outlines (coverage 1), and the
    // larger perimeter ranks first, so the cards take the first four places.
    scene::SceneOptions o;
    o.background = 50;
    o.blur_sigma = 0.7;
    o.noise_sigma = 2;
    o.seed = 4;
    scene::LineScene ls(o);
    const std::pair<double, double> cards[4] = {{6, 6}, {204, 6}, {6, 154}, {204, 154}};
    for (const auto& [x0, y0] : cards) {
        ls.add_polygon({{x0, y0}, {x0 + 1, y0 + 80}, {x0 + 110, y0 + 81}, {x0 + 109, y0 + 1}}, 215);
        for (double y = y0 + 12; y + 4 < y0 + 72; y += 8)
            for (double x = x0 + 12; x + 12 < x0 + 100; x += 17)
                ls.add_polygon({{x, y}, {x + 12, y}, {x + 12, y + 4}, {x, y + 4}}, 90);
    }
    const std::vector<scene::Point2> board = {
        {130.4, 96.2}, {131.1, 142.5}, {190.3, 143.6}, {189.6, 95.1}};
    ls.add_polygon(board, 235);
    const io::GreyImage img = ls.render();
    BoardParams params;
    const Status s = io::push_frame(g_det, img, params);
    REQUIRE((s == Status::ok || s == Status::capacity_exceeded));
    CHECK(found(g_det, board));
    CHECK(g_det.quad_stats().rejected_interior >= 1);
    REQUIRE(io::push_frame(g_four, img, params) == s);
    CHECK(!found(g_four, board));
}

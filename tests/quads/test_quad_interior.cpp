// The inside of a quadrangle (quad_interior.h): cells holding edge points counted against a
// square worked by hand, the limit's arithmetic by hand, and the detector keeping a blank board
// while it turns down a printed rectangle of the same outline.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/prng.h"
#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "quads/quad_interior.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

Point16 corner(int32_t x, int32_t y) { return {q16_16::from_int(x), q16_16::from_int(y)}; }

// How far (x, y) lies inside the convex quadrangle q (corners in order, either winding): the
// least signed distance from its four sides' lines, px, positive inside.
double inside_by(const double q[4][2], double x, double y) {
    double area2 = 0;
    for (int i = 0; i < 4; ++i) area2 += q[i][0] * q[(i + 1) % 4][1] - q[(i + 1) % 4][0] * q[i][1];
    const double sign = area2 > 0 ? 1 : -1;
    double least = 1e9;
    for (int i = 0; i < 4; ++i) {
        const double dx = q[(i + 1) % 4][0] - q[i][0], dy = q[(i + 1) % 4][1] - q[i][1];
        const double d = sign * (dx * (y - q[i][1]) - dy * (x - q[i][0])) / std::hypot(dx, dy);
        least = std::min(least, d);
    }
    return least;
}

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

namespace {

// Cells (x / 2, y / 2) of the points strictly inside the convex quadrangle q (corners in
// order, either winding) and farther than `margin` px from every side, in doubles: the
// definition, with none of count_inside_edges' integer arithmetic.
uint32_t reference_cells(const std::vector<std::pair<uint16_t, uint16_t>>& points,
                         const double q[4][2], double margin) {
    std::vector<std::pair<int, int>> cells;
    for (auto [x, y] : points)
        if (inside_by(q, x, y) > margin) cells.emplace_back(x / 2, y / 2);
    std::sort(cells.begin(), cells.end());
    return static_cast<uint32_t>(std::unique(cells.begin(), cells.end()) - cells.begin());
}

}  // namespace

TEST_CASE("cells inside random quadrangles: the row intervals against a per-point reference",
          "[interior]") {
    // 300 convex quadrangles with corners on the 1/16 px grid, in a 160 × 120 frame a quarter
    // of whose pixels hold a point; margins 0..7 px (the detector's range is 0..16). Points
    // within 0.02 px of the margin are left out: there the rounded side lengths of the integer
    // test may decide either way.
    Pcg32 rng(20261127);
    constexpr int kW = 160, kH = 120;
    static EdgeListStorage<8192, kH> storage;
    int compared = 0, nonzero = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const double cx = 30 + rng.below(100), cy = 25 + rng.below(70);
        const double r = 8 + rng.below(60);
        const double a0 = rng.below(360) * M_PI / 180;
        double q[4][2];
        for (int i = 0; i < 4; ++i) {
            const double a = a0 + (i * 90 + static_cast<int>(rng.below(50)) - 25) * M_PI / 180;
            const double ri = r * (0.6 + rng.below(400) / 1000.0);
            q[i][0] = std::round((cx + ri * std::cos(a)) * 16) / 16;
            q[i][1] = std::round((cy + ri * std::sin(a)) * 16) / 16;
        }
        if (trial % 2) std::swap(q[1], q[3]);  // the other winding
        const double margin = rng.below(8);
        std::vector<std::pair<uint16_t, uint16_t>> points;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (rng.below(4) == 0 && std::fabs(inside_by(q, x, y) - margin) > 0.02)
                    points.emplace_back(x, y);
        EdgeList list = storage.view();
        REQUIRE(list.begin_frame(kH) == Status::ok);
        int32_t row = -1;
        for (auto [x, y] : points) {
            if (y != row) list.begin_row(y), row = y;
            REQUIRE(list.push(x, 0, 0, 100));
        }
        list.end_frame();
        Point16 corners[4];
        for (int i = 0; i < 4; ++i)
            corners[i] = {q16_16::from_raw(static_cast<int32_t>(q[i][0] * 65536)),
                          q16_16::from_raw(static_cast<int32_t>(q[i][1] * 65536))};
        const uint32_t expected = reference_cells(points, q, margin);
        const uint32_t got =
            count_inside_edges(list, corners, q16_16::from_int(static_cast<int32_t>(margin))).cells;
        INFO("trial " << trial << " margin " << margin);
        CHECK(got == expected);
        ++compared;
        nonzero += expected > 0;
    }
    CHECK(compared == 300);
    CHECK(nonzero > 200);  // most quadrangles hold points: the comparison is not of zeros
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
    CHECK(interior_clear({400, 1600}, 240, kCheckOff));  // off: not tested
    CHECK(!interior_clear({1, 1600}, 240, 0));
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
    params.refine.max_inside_edge_cells_percent = kCheckOff;
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

namespace {

Segment seg(int32_t x1, int32_t y1, int32_t x2, int32_t y2) {
    Segment s{};
    s.x1 = q16_16::from_int(x1), s.y1 = q16_16::from_int(y1);
    s.x2 = q16_16::from_int(x2), s.y2 = q16_16::from_int(y2);
    return s;
}

}  // namespace

TEST_CASE("lines across a square: inside over the least length and out past a side", "[interior]") {
    // The square (10, 10)–(50, 50), margin 4: "inside" is 14 < x, y < 46, "outside" is beyond
    // 6 ≤ x, y ≤ 54, and a line counts with at least 20 px inside and 4 px outside.
    const Point16 sq[4] = {corner(10, 10), corner(10, 50), corner(50, 50), corner(50, 10)};
    const q16_16 m = q16_16::from_int(4), least = q16_16::from_int(20);
    auto across = [&](const Segment& s) { return count_lines_across(&s, 1, sq, m, least); };
    CHECK(across(seg(0, 30, 60, 30)) == 1);   // right through: 32 px in, 6 + 6 px out
    CHECK(across(seg(30, 0, 30, 60)) == 1);   // the same, upright
    CHECK(across(seg(60, 30, 0, 30)) == 1);   // either direction
    CHECK(across(seg(0, 30, 40, 30)) == 1);   // in from the left (26 px in, 6 out), ends inside
    CHECK(across(seg(20, 30, 44, 30)) == 0);  // print: 24 px in, never out
    CHECK(across(seg(0, 30, 30, 30)) == 0);   // 16 px in: too little
    CHECK(across(seg(9, 30, 60, 30)) == 1);   // 32 px in, 6 px out on the right only
    CHECK(across(seg(9, 30, 57, 30)) == 0);   // 3 px out: within the margin's reach
    CHECK(across(seg(10, 0, 10, 60)) == 0);   // along a side: never inside by the margin
    CHECK(across(seg(0, 70, 60, 70)) == 0);   // outside
    CHECK(across(seg(0, 0, 60, 60)) == 1);    // the diagonal: 45 px in
    const Segment all[] = {seg(0, 30, 60, 30), seg(30, 0, 30, 60), seg(20, 30, 44, 30)};
    CHECK(count_lines_across(all, 3, sq, m, least) == 2);
    const Point16 cw[4] = {sq[0], sq[3], sq[2], sq[1]};  // either winding
    CHECK(count_lines_across(all, 3, cw, m, least) == 2);
}

namespace {

// A checkerboard target: 8 × 6 squares of 28 px (grey 30 on a card of grey 225, 8 px of card
// round the pattern), turned 8°, on a grey background. The card is a bright quadrangle; the
// pattern's lines make more of every size.
struct Checkerboard {
    io::GreyImage image;
    std::vector<scene::Point2> card;
};

Checkerboard checkerboard_frame() {
    scene::SceneOptions o;
    o.background = 120;
    o.blur_sigma = 0.8;
    o.noise_sigma = 3;
    o.seed = 5;
    scene::LineScene ls(o);
    const double c = std::cos(8 * M_PI / 180), s = std::sin(8 * M_PI / 180);
    auto at = [&](double u, double v) {
        return scene::Point2{160 + c * (u - 112) - s * (v - 84),
                             120 + s * (u - 112) + c * (v - 84)};
    };
    Checkerboard b;
    b.card = {at(-8, -8), at(-8, 176), at(232, 176), at(232, -8)};
    ls.add_polygon(b.card, 225);
    for (int row = 0; row < 6; ++row)
        for (int col = 0; col < 8; ++col) {
            if ((row + col) % 2) continue;
            const double u = col * 28, v = row * 28;
            ls.add_polygon({at(u, v), at(u, v + 28), at(u + 28, v + 28), at(u + 28, v)}, 30);
        }
    b.image = ls.render();
    return b;
}

// Whether every corner of q lies within 3 px of a corner of `outline`.
bool is_outline(const Quad& q, const std::vector<scene::Point2>& outline) {
    for (int i = 0; i < 4; ++i) {
        bool near = false;
        for (const scene::Point2& t : outline)
            near = near || std::hypot(q.corners[i].x.raw / 65536.0 - t.x,
                                      q.corners[i].y.raw / 65536.0 - t.y) < 3;
        if (!near) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("no quadrangle is cut out of a checkerboard's lines", "[interior]") {
    // Without the test the card comes with quadrangles whose sides are the card's border and the
    // pattern's lines; each of those is crossed by the pattern's other lines, the card is not
    // (its lines end at the pattern's border, inside it).
    const Checkerboard board = checkerboard_frame();
    BoardParams params;
    params.refine.max_lines_across = kCheckOff;
    const Status s = io::push_frame(g_det, board.image, params);
    REQUIRE((s == Status::ok || s == Status::capacity_exceeded));
    int cut_out = 0;
    for (uint16_t q = 0; q < g_det.quad_count(); ++q)
        cut_out += !is_outline(g_det.quads()[q], board.card);
    CHECK(cut_out >= 1);
    CHECK(g_det.quad_stats().rejected_across == 0);

    params.refine.max_lines_across = BoardParams{}.refine.max_lines_across;
    REQUIRE(io::push_frame(g_det, board.image, params) == s);
    REQUIRE(g_det.quad_count() >= 1);
    for (uint16_t q = 0; q < g_det.quad_count(); ++q)
        CHECK(is_outline(g_det.quads()[q], board.card));
    CHECK(g_det.quad_stats().rejected_across >= 1);
}

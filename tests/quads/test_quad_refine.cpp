// Side refinement, edge evidence and completion of a hidden side (quad_refine.h,
// detect_quads' completion): against the geometry the scenes were drawn with and against the
// verification rule worked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "io/push_frame.h"
#include "lines/line_fit.h"
#include "quads/board_detector.h"
#include "scene/board_pose.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

// The board of these tests, anti-clockwise as seen: top-left, bottom-left, bottom-right,
// top-right (px).
const scene::Point2 kCorners[4] = {{60.3, 50.7}, {70.2, 180.4}, {250.6, 170.1}, {240.8, 40.2}};

io::GreyImage board_frame(uint8_t right_of_board = 60) {
    scene::SceneOptions o;
    o.background = 60;
    o.blur_sigma = 0.8;
    o.noise_sigma = 3;
    o.seed = 12;
    scene::LineScene ls(o);
    // Optionally the area right of the board's right side (its line, to the frame's edges) as
    // bright as the board: that side vanishes.
    const scene::Point2 tr = kCorners[3], br = kCorners[2];
    auto x_at = [&](double y) { return tr.x + (y - tr.y) * (br.x - tr.x) / (br.y - tr.y); };
    ls.add_polygon({{x_at(-5), -5}, {330, -5}, {330, 250}, {x_at(250), 250}}, right_of_board);
    ls.add_polygon({kCorners, kCorners + 4}, 220);
    return ls.render();
}

q16_16 q(double v) { return q16_16::from_raw(static_cast<int32_t>(std::lround(v * 65536))); }

// The line through a and b moved `shift` px along its normal and turned `turn_deg` about its
// middle, with the board (brighter) on the side of `inside`.
Segment line_near(scene::Point2 a, scene::Point2 b, double shift, double turn_deg,
                  scene::Point2 inside) {
    const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2, len = std::hypot(b.x - a.x, b.y - a.y);
    const double t = std::atan2(b.y - a.y, b.x - a.x) + turn_deg * 3.14159265358979323846 / 180;
    double dx = std::cos(t), dy = std::sin(t);
    if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
    FittedLine l;
    l.mx = q(mx - dy * shift);
    l.my = q(my + dx * shift);
    l.dx = q2_30::from_raw(static_cast<int32_t>(std::lround(dx * 1073741824.0)));
    l.dy = q2_30::from_raw(static_cast<int32_t>(std::lround(dy * 1073741824.0)));
    Segment s = make_segment(l, q(-len / 2), q(len / 2), 100);
    const double th = s.theta * (2 * 3.14159265358979323846 / 4294967296.0);
    const double side = (inside.x * std::cos(th) + inside.y * std::sin(th)) - s.rho.raw / 65536.0;
    s.bright_side = side > 0 ? int8_t{1} : int8_t{-1};
    return s;
}

// The quadrangle whose sides are the exact lines through corners c (side i from c[i] to
// c[i + 1]), the board's inside at `inside`: its lines in start, pointed to by side_lines.
Quad exact_quad(const scene::Point2 c[4], scene::Point2 inside, Segment start[4],
                const Segment* side_lines[4]) {
    Quad quad{};
    for (int i = 0; i < 4; ++i) {
        start[i] = line_near(c[i], c[(i + 1) % 4], 0, 0, inside);
        side_lines[i] = &start[i];
    }
    for (int i = 0; i < 4; ++i)
        REQUIRE(intersect_lines(start[(i + 3) % 4], start[i], quad.corners[i]));
    return quad;
}

LineDetectorQvga g_lines;

}  // namespace

TEST_CASE("refined sides put the corners on the true corners from lines a few pixels off",
          "[refine]") {
    const io::GreyImage img = board_frame();
    REQUIRE(io::push_frame(g_lines, img, LineParams{}) == Status::ok);
    const scene::Point2 centre{155, 110};
    // Each side's starting line 1.5 px off and turned 1°, alternately either way.
    Segment start[4];
    const Segment* side_lines[4];
    for (int i = 0; i < 4; ++i) {
        start[i] = line_near(kCorners[i], kCorners[(i + 1) % 4], i % 2 ? 1.5 : -1.5,
                             i % 2 ? 1.0 : -1.0, centre);
        side_lines[i] = &start[i];
    }
    Quad quad{};
    for (int i = 0; i < 4; ++i) {
        REQUIRE(intersect_lines(start[(i + 3) % 4], start[i], quad.corners[i]));
        quad.lines[i] = static_cast<uint8_t>(i);
    }
    double before = 0;
    for (int i = 0; i < 4; ++i)
        before = std::fmax(before, std::hypot(quad.corners[i].x.raw / 65536.0 - kCorners[i].x,
                                              quad.corners[i].y.raw / 65536.0 - kCorners[i].y));
    REQUIRE(before > 2);  // the starting corners are well off

    Segment sides[4];
    SideEvidence evidence{};
    Quad verified = quad;
    Segment verified_sides[4];
    q16_16 verified_share;
    REQUIRE(refine_quad(g_lines.edges(), side_lines, RefineParams{}, quad, sides, &evidence) ==
            0xF);
    for (int i = 0; i < 4; ++i) {
        const double e = std::hypot(quad.corners[i].x.raw / 65536.0 - kCorners[i].x,
                                    quad.corners[i].y.raw / 65536.0 - kCorners[i].y);
        INFO("corner " << i << " off by " << e << " px");
        CHECK(e < 0.25);
        CHECK(evidence.held[i] * 10 >= evidence.steps[i] * 9);  // edge evidence along 90 % or more
        CHECK(evidence.ends[i] == 3);
        CHECK(sides[i].bright_side == start[i].bright_side);
    }
    q16_16 share;
    CHECK(verify_evidence(evidence, 0, RefineParams{}, &share));
    CHECK(share.raw > 58982);  // > 0.9
    // In one call, as the detector keeps a candidate: the same corners, sides and share.
    REQUIRE(refine_verified(g_lines.edges(), side_lines, RefineParams{}, verified, verified_sides,
                            &verified_share));
    CHECK(verified_share == share);
    for (int i = 0; i < 4; ++i) {
        CHECK(verified.corners[i].x == quad.corners[i].x);
        CHECK(verified.corners[i].y == quad.corners[i].y);
        CHECK(verified_sides[i].rho == sides[i].rho);
        CHECK(verified_sides[i].theta == sides[i].theta);
    }
}

TEST_CASE("refinement off: the corners stay where the lines cross, the evidence is along them",
          "[refine]") {
    const io::GreyImage img = board_frame();
    REQUIRE(io::push_frame(g_lines, img, LineParams{}) == Status::ok);
    // Exact lines give evidence along every side; the same lines 2 px off give almost none
    // within fine_band (1 px), as nothing moves them onto the edges.
    RefineParams off;
    off.band = q16_16::from_int(0);
    for (const double shift : {0.0, 2.0}) {
        Segment start[4];
        const Segment* side_lines[4];
        for (int i = 0; i < 4; ++i) {
            start[i] = line_near(kCorners[i], kCorners[(i + 1) % 4], shift, 0, {155, 110});
            side_lines[i] = &start[i];
        }
        Quad quad{};
        for (int i = 0; i < 4; ++i)
            REQUIRE(intersect_lines(start[(i + 3) % 4], start[i], quad.corners[i]));
        const Quad given = quad;
        Segment sides[4];
        SideEvidence evidence{};
        INFO("lines " << shift << " px off");
        REQUIRE(refine_quad(g_lines.edges(), side_lines, off, quad, sides, &evidence) == 0);
        for (int i = 0; i < 4; ++i) {
            CHECK(quad.corners[i].x == given.corners[i].x);
            CHECK(quad.corners[i].y == given.corners[i].y);
            CHECK(sides[i].rho == start[i].rho);
            if (shift == 0)
                CHECK(evidence.held[i] * 10 >= evidence.steps[i] * 9);
            else
                CHECK(evidence.held[i] * 10 < evidence.steps[i]);
        }
        // With refinement (first band 2.5 px) every side is refitted.
        Quad refined = given;
        CHECK(refine_quad(g_lines.edges(), side_lines, RefineParams{}, refined, sides) == 0xF);
    }
}

TEST_CASE("a side without edges keeps its line and the evidence turns the quadrangle down",
          "[refine]") {
    const io::GreyImage img = board_frame(220);  // right of the board as bright as the board
    REQUIRE(io::push_frame(g_lines, img, LineParams{}) == Status::ok);
    Segment start[4];
    const Segment* side_lines[4];
    Quad quad = exact_quad(kCorners, {155, 110}, start, side_lines);
    Quad verified = quad;
    Segment sides[4];
    SideEvidence evidence{};
    const uint8_t refitted =
        refine_quad(g_lines.edges(), side_lines, RefineParams{}, quad, sides, &evidence);
    CHECK((refitted & 4u) == 0);  // side 2, bottom-right -> top-right: no edge there
    CHECK(refitted == 0xB);
    CHECK(evidence.held[2] * 10 < evidence.steps[2]);
    CHECK(sides[2].rho == start[2].rho);
    q16_16 share;
    CHECK_FALSE(verify_evidence(evidence, 0, RefineParams{}, &share));
    CHECK_FALSE(
        verify_evidence(evidence, 4, RefineParams{}, &share));  // not even as a completed side
    // In one call: turned down at side 2 (side 3 is not walked).
    CHECK_FALSE(
        refine_verified(g_lines.edges(), side_lines, RefineParams{}, verified, sides, &share));
    // Unless the side checks are off.
    RefineParams keep_all;
    keep_all.min_side_evidence_percent = kCheckOff;
    keep_all.min_hidden_side_evidence_percent = kCheckOff;
    CHECK(refine_verified(g_lines.edges(), side_lines, keep_all, verified, sides, &share));
}

TEST_CASE("edge evidence rule: each side, the hidden one, both ends, the whole", "[refine]") {
    const RefineParams p;  // 30 % a side, 20 % a completed side, 60 % in all
    auto evidence = [](uint16_t a, uint16_t b, uint16_t c, uint16_t d) {
        SideEvidence e{};
        const uint16_t held[4] = {a, b, c, d};
        for (int i = 0; i < 4; ++i) {
            e.steps[i] = 100;
            e.held[i] = held[i];
            e.ends[i] = 3;
        }
        return e;
    };
    q16_16 share;
    CHECK(verify_evidence(evidence(100, 100, 100, 30), 0, p, &share));
    CHECK(share == q16_16::from_ratio(330, 400));
    CHECK_FALSE(verify_evidence(evidence(100, 100, 100, 29), 0, p, &share));
    CHECK(verify_evidence(evidence(100, 100, 100, 20), 8, p, &share));  // side 3 completed
    CHECK_FALSE(verify_evidence(evidence(100, 100, 100, 19), 8, p, &share));
    CHECK(verify_evidence(evidence(60, 60, 60, 60), 0, p, &share));  // 60 % in all, exactly
    CHECK_FALSE(verify_evidence(evidence(60, 60, 60, 59), 0, p, &share));
    SideEvidence one_end = evidence(100, 100, 100, 100);
    one_end.ends[1] = 2;  // side 1 shows near its second corner only
    CHECK_FALSE(verify_evidence(one_end, 0, p, &share));
    SideEvidence none = evidence(0, 0, 0, 0);
    none.steps[0] = 0;
    CHECK_FALSE(verify_evidence(none, 0, p, &share));
}

TEST_CASE("edge evidence: a step between two held steps is held, a longer gap is not", "[refine]") {
    // A bright 161 × 101 px rectangle, corners (40, 40) and (200, 140), drawn straight into an
    // edge list: its sides' points on every `every`-th step of their own axis (x along the top
    // and bottom, y down the left and right), gradient directions from dark to bright (bins
    // 4, 12 for top and bottom, 0, 8 for left and right). Each side spans (161 or 101) − 2 ·
    // (3 px end margin) steps; by hand: every step held at 1, every other step held filled in
    // at 2 (the thinning of a full list, edge_list.h), a third at 3.
    for (const uint16_t every : {1, 2, 3}) {
        EdgeListStorage<1024, 240> storage;
        EdgeList list = storage.view();
        REQUIRE(list.begin_frame(240) == Status::ok);
        for (uint16_t y = 0; y < 240; ++y) {
            list.begin_row(y);
            if (y == 40 || y == 140) {
                for (uint16_t x = 40; x <= 200; ++x)
                    if (x % every == 0) list.push(x, y == 40 ? 4 : 12, 0, 100);
            } else if (y > 40 && y < 140 && y % every == 0) {
                list.push(40, 0, 0, 100);
                list.push(200, 8, 0, 100);
            }
        }
        list.end_frame();
        const scene::Point2 c[4] = {{40, 40}, {40, 140}, {200, 140}, {200, 40}};
        Segment start[4];
        const Segment* side_lines[4];
        Quad quad = exact_quad(c, {120, 90}, start, side_lines);
        Segment sides[4];
        SideEvidence evidence{};
        refine_quad(list, side_lines, RefineParams{}, quad, sides, &evidence);
        for (int i = 0; i < 4; ++i) {
            INFO("every " << every << " side " << i << ": " << evidence.held[i] << " of "
                          << evidence.steps[i]);
            const uint32_t steps = evidence.steps[i];
            CHECK((steps == 155 || steps == 95));
            // Steps 43 .. 137 (or 197): all; all but the two odd end steps, which have no held
            // step beyond them; the multiples of 3, 45 .. 135 (or 195).
            const uint32_t held[4] = {0, steps, steps - 2, (steps == 95 ? 135u : 195u) / 3 - 14};
            CHECK(evidence.held[i] == held[every]);
        }
        q16_16 share;
        CHECK(verify_evidence(evidence, 0, RefineParams{}, &share) == (every <= 2));
    }
}

TEST_CASE("completion: a board whose side is hidden but for its two ends is found", "[refine]") {
    // A 90 × 70 px board; a dark arm from below hides the middle 60 % of its bottom side, so
    // the two visible pieces (18 px) are shorter than min_line_length: no line is found along
    // it, and only completion from the left and right sides finds the board.
    const scene::Point2 c[4] = {{110.4, 80.3}, {112.6, 150.7}, {202.2, 148.1}, {199.7, 77.6}};
    scene::SceneOptions o;
    o.background = 50;
    o.blur_sigma = 0.7;
    o.noise_sigma = 2;
    scene::LineScene ls(o);
    ls.add_polygon({c, c + 4}, 215);
    const double a = 0.2, b = 0.8;  // the covered part of the bottom side
    const scene::Point2 p{c[1].x + a * (c[2].x - c[1].x), c[1].y + a * (c[2].y - c[1].y)};
    const scene::Point2 r{c[1].x + b * (c[2].x - c[1].x), c[1].y + b * (c[2].y - c[1].y)};
    // The arm: from below the frame, a rounded tip 20 px inside the side
    // (platform/scene/board_pose.h).
    const double len = std::hypot(c[2].x - c[1].x, c[2].y - c[1].y);
    const double nx = (c[2].y - c[1].y) / len, ny = -(c[2].x - c[1].x) / len;  // inward normal
    const std::vector<scene::Point2> tip = scene::arm_tip(p, r, -nx, -ny, 1, (b - a) * len, 20);
    ls.add_polygon(scene::arm_outline(p, r, tip, -nx, -ny, 320, 240), 30);
    const io::GreyImage img = ls.render();

    static BoardDetectorQvga det;
    BoardParams params;
    REQUIRE(io::push_frame(det, img, params) == Status::ok);
    REQUIRE(det.quad_count() >= 1);
    for (int i = 0; i < 4; ++i) {
        const double e = std::hypot(det.quads()[0].corners[i].x.raw / 65536.0 - c[i].x,
                                    det.quads()[0].corners[i].y.raw / 65536.0 - c[i].y);
        INFO("corner " << i << " off by " << e << " px");
        CHECK(e < 1.0);
    }
    // The completed side joined the line list, and the quadrangle's lines all index it.
    for (int i = 0; i < 4; ++i) CHECK(det.quads()[0].lines[i] < det.lines().line_count());
    CHECK(det.quad_stats().completions > 0);

    params.quads.complete_hidden_side = false;
    REQUIRE(io::push_frame(det, img, params) == Status::ok);
    CHECK(det.quad_count() == 0);
}

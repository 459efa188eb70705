// The five rules of section 2.4, each with a hand-worked case that passes and one that fails,
// line intersections against double precision, and the candidate search on hand-built lines.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "base/prng.h"
#include "quads/quad_detector.h"
#include "scene/board_pose.h"
#include "support/segment_reference.h"

using namespace qt;
using qt::ref::angle_deg;
using qt::ref::from_q16;
using qt::ref::segment;
using qt::ref::to_q16;

namespace {

Point16 pt(double x, double y) { return {to_q16(x), to_q16(y)}; }

struct Found {
    Status status;
    std::vector<Quad> quads;
    QuadStats stats;
};

Found find(const std::vector<Segment>& lines, uint16_t w, uint16_t h,
           const QuadParams& p = QuadParams{}, uint16_t pair_capacity = 64, uint16_t capacity = 4) {
    std::vector<LinePair> pairs(pair_capacity);
    std::vector<QuadLine> geometry(lines.size() + 1);
    std::vector<Quad> out(capacity);
    Found f;
    f.status = detect_quads(lines.data(), static_cast<uint16_t>(lines.size()), w, h, p,
                            {pairs.data(), pair_capacity, geometry.data(), out.data(), capacity},
                            &f.stats);
    f.quads.assign(out.begin(), out.begin() + f.stats.quads);
    return f;
}

// The four sides of the polygon a, b, c, d as segments covering each side fully.
std::vector<Segment> sides_of(Point16 a, Point16 b, Point16 c, Point16 d) {
    const Point16 v[4] = {a, b, c, d};
    std::vector<Segment> s;
    for (int i = 0; i < 4; ++i)
        s.push_back(segment(from_q16(v[i].x), from_q16(v[i].y), from_q16(v[(i + 1) % 4].x),
                            from_q16(v[(i + 1) % 4].y)));
    return s;
}

void require_corner(const Point16& c, double x, double y, double tol = 1e-3) {
    INFO("corner (" << from_q16(c.x) << ", " << from_q16(c.y) << ") expected (" << x << ", " << y
                    << ")");
    REQUIRE(std::fabs(from_q16(c.x) - x) <= tol);
    REQUIRE(std::fabs(from_q16(c.y) - y) <= tol);
}

}  // namespace

TEST_CASE("rule 1: opposite sides almost parallel", "[quad]") {
    QuadParams p;
    p.parallel_tolerance = angle_from_deg(10);
    CHECK(rule_parallel(angle_deg(20), angle_deg(29), p));
    CHECK_FALSE(rule_parallel(angle_deg(20), angle_deg(31), p));
    // Orientation is modulo 180°: normals at 178° and 3° (or 183°) are 5° apart as lines.
    CHECK(rule_parallel(angle_deg(178), angle_deg(3), p));
    CHECK(rule_parallel(angle_deg(178), angle_deg(183), p));
    CHECK_FALSE(rule_parallel(angle_deg(0), angle_deg(90), p));
}

TEST_CASE("rule 2: adjacent sides almost perpendicular", "[quad]") {
    QuadParams p;
    p.perpendicular_tolerance = angle_from_deg(20);
    CHECK(rule_perpendicular(angle_deg(0), angle_deg(90), p));
    CHECK(rule_perpendicular(angle_deg(0), angle_deg(71), p));          // 19° off
    CHECK_FALSE(rule_perpendicular(angle_deg(0), angle_deg(69), p));    // 21° off
    CHECK(rule_perpendicular(angle_deg(350), angle_deg(265), p));       // 85° apart
    CHECK_FALSE(rule_perpendicular(angle_deg(10), angle_deg(190), p));  // the same line
}

TEST_CASE("rule 3: corners inside the image", "[quad]") {
    QuadParams p;  // the frame 320 × 240 spans [-0.5, 319.5] × [-0.5, 239.5]
    const Point16 in[4] = {pt(-0.5, -0.5), pt(-0.5, 239.5), pt(319.5, 239.5), pt(319.5, -0.5)};
    CHECK(rule_corners_inside(in, 320, 240, p));
    const Point16 out_x[4] = {pt(10, 10), pt(10, 200), pt(319.51, 200), pt(300, 10)};
    CHECK_FALSE(rule_corners_inside(out_x, 320, 240, p));
    const Point16 out_y[4] = {pt(10, -0.51), pt(10, 200), pt(300, 200), pt(300, 10)};
    CHECK_FALSE(rule_corners_inside(out_y, 320, 240, p));
    p.corner_margin = q16_16::from_int(2);  // now [1.5, 317.5] × [1.5, 237.5]
    const Point16 near[4] = {pt(1.5, 1.5), pt(1.5, 237.5), pt(317.5, 237.5), pt(317.5, 1.5)};
    CHECK(rule_corners_inside(near, 320, 240, p));
    const Point16 edge[4] = {pt(1.4, 1.5), pt(1.5, 237.5), pt(317.5, 237.5), pt(317.5, 1.5)};
    CHECK_FALSE(rule_corners_inside(edge, 320, 240, p));
}

TEST_CASE("rule 4: side lengths between the limits", "[quad]") {
    QuadParams p;
    p.min_side_length = q16_16::from_int(20);
    p.max_side_length = q16_16::from_int(100);
    const q16_16 ok[4] = {q16_16::from_int(20), q16_16::from_int(100), q16_16::from_int(50),
                          q16_16::from_int(60)};
    CHECK(rule_side_lengths(ok, p));
    const q16_16 short_side[4] = {q16_16::from_int(50), to_q16(19.99), q16_16::from_int(50),
                                  q16_16::from_int(60)};
    CHECK_FALSE(rule_side_lengths(short_side, p));
    const q16_16 long_side[4] = {q16_16::from_int(50), q16_16::from_int(50), to_q16(100.01),
                                 q16_16::from_int(60)};
    CHECK_FALSE(rule_side_lengths(long_side, p));
}

TEST_CASE("rule 5: adjacent-side ratio close to the display's", "[quad]") {
    QuadParams p;  // 4:3 display, factor 1.8 either way: ratio in [0.7407, 2.4]
    auto sides = [](double left, double bottom, double right, double top) {
        return std::vector<q16_16>{to_q16(left), to_q16(bottom), to_q16(right), to_q16(top)};
    };
    CHECK(rule_aspect(sides(60, 80, 60, 80).data(), 0, p));          // exactly 4:3
    CHECK(rule_aspect(sides(100, 75, 100, 75).data(), 0, p));        // 0.75
    CHECK_FALSE(rule_aspect(sides(100, 73, 100, 73).data(), 0, p));  // 0.73
    CHECK(rule_aspect(sides(50, 119, 50, 119).data(), 0, p));        // 2.38
    CHECK_FALSE(rule_aspect(sides(50, 121, 50, 121).data(), 0, p));  // 2.42
    // Means of opposite sides: (70 + 90) / (50 + 70) = 4/3 though no single pair is.
    CHECK(rule_aspect(sides(50, 70, 70, 90).data(), 0, p));
    p.aspect_tolerance = q16_16::from_ratio(11, 10);               // [1.2121, 1.4667]
    CHECK_FALSE(rule_aspect(sides(50, 60, 50, 60).data(), 0, p));  // 1.2
    CHECK(rule_aspect(sides(50, 61, 50, 61).data(), 0, p));        // 1.22
}

TEST_CASE("rule 5: a larger factor for a quadrangle whose sides converge", "[quad]") {
    QuadParams p;  // 1.8, or 2.2 when a pair of opposite sides converges by >= 4 degrees
    auto sides = [](double left, double bottom, double right, double top) {
        return std::vector<q16_16>{to_q16(left), to_q16(bottom), to_q16(right), to_q16(top)};
    };
    const angle_t under = angle_from_deg(4) - 1, at = angle_from_deg(4);
    // Ratio 160 / 60 = 2.667, factor 2.0 above 4:3; 80 / 120 = 0.667, factor 2.0 below it.
    CHECK_FALSE(rule_aspect(sides(30, 80, 30, 80).data(), under, p));
    CHECK(rule_aspect(sides(30, 80, 30, 80).data(), at, p));
    CHECK_FALSE(rule_aspect(sides(60, 40, 60, 40).data(), under, p));
    CHECK(rule_aspect(sides(60, 40, 60, 40).data(), at, p));
    // Ratio 2.9 (factor 2.175) passes, 3.0 (factor 2.25) does not, however strong the
    // convergence.
    CHECK(rule_aspect(sides(20, 58, 20, 58).data(), angle_from_deg(30), p));
    CHECK_FALSE(rule_aspect(sides(20, 60, 20, 60).data(), angle_from_deg(30), p));
    // The larger of the two tolerances holds.
    p.aspect_tolerance = q16_16::from_ratio(5, 2);  // ratio up to 3.333
    CHECK(rule_aspect(sides(20, 60, 20, 60).data(), 0, p));
    // Convergence: the larger orientation difference of the two opposite pairs. Left side
    // vertical, right side 5 degrees off it (tan 5° · 100 = 8.749 px), top and bottom 1 degree
    // apart.
    const Segment left = segment(0, 0, 0, 100), right = segment(150, 0, 158.749, 100);
    const Segment top = segment(0, 0, 150, 0), bottom = segment(0, 100, 150, 102.618);
    const Segment* quad[4] = {&left, &bottom, &right, &top};
    CHECK(std::abs(opposite_convergence(quad) / 4294967296.0 * 360.0 - 5.0) < 0.01);
}

TEST_CASE("rule 5 passes the boards of the photo bench's poses, at any aspect", "[quad]") {
    // The brief's boards (aspect 1:1, 4:3 or 16:9; tilt <= 35 deg, roll <= 25 deg, 25-70 % of
    // the frame) under the benches' pinhole camera (focal length = frame width), in
    // detect_quads' corner order, against the default 4:3 display. Reference: the poses'
    // corners in double precision (scene/board_pose.h).
    const double aspects[3] = {1.0, 4.0 / 3, 16.0 / 9};
    const int sizes[2][2] = {{320, 240}, {640, 480}};
    QuadParams no_allowance;
    no_allowance.perspective_convergence = kAngleQuarterTurn + 1;  // never reached
    for (const auto& size : sizes) {
        const scene::PinholeCamera cam = scene::centred_camera(size[0], size[1], 0);
        for (double aspect : aspects) {
            Pcg32 rng(2024, 5);
            int failed = 0, failed_without = 0;
            const int n = 2000;
            for (int i = 0; i < n; ++i) {
                scene::Point2 c[4];
                scene::place_board(cam, aspect, {0, 35, -25, 25, 0.25, 0.7}, rng, c);
                int first = 0;
                for (int k = 1; k < 4; ++k)
                    if (c[k].x + c[k].y < c[first].x + c[first].y) first = k;
                q16_16 lengths[4];
                Segment lines[4];
                const Segment* line_ptrs[4];
                for (int k = 0; k < 4; ++k) {
                    const scene::Point2 a = c[(first + k) & 3], b = c[(first + k + 1) & 3];
                    lengths[k] = to_q16(std::hypot(b.x - a.x, b.y - a.y));
                    lines[k] = segment(a.x, a.y, b.x, b.y);
                    line_ptrs[k] = &lines[k];
                }
                const angle_t convergence = opposite_convergence(line_ptrs);
                failed += !rule_aspect(lengths, convergence, QuadParams{});
                failed_without += !rule_aspect(lengths, convergence, no_allowance);
            }
            CAPTURE(size[0], aspect, failed, failed_without);
            CHECK(failed <= 2);  // 0.1 %: a roll near 25° can make another corner the first
            // Without the allowance, the 1:1 boards tilted most are turned down (0.7 %).
            if (aspect == 1.0) CHECK(failed_without >= 5);
        }
    }
}

TEST_CASE("line intersections agree with double precision", "[quad]") {
    Point16 c;
    // x = 10 and y = 20: exactly (10, 20).
    REQUIRE(intersect_lines(segment(10, 0, 10, 50), segment(0, 20, 50, 20), c));
    require_corner(c, 10, 20, 1.0 / 65536);
    // Parallel lines do not cross.
    CHECK_FALSE(intersect_lines(segment(0, 0, 100, 10), segment(0, 30, 100, 40), c));
    Pcg32 rng(7, 1);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * (rng.next() / 4294967296.0); };
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        const double x = u(-50, 700), y = u(-50, 500);  // the crossing
        const double a1 = u(0, 2 * ref::kPi), a2 = a1 + u(0.3, 2.8);
        const double l1 = u(20, 200), l2 = u(20, 200);
        const Segment s1 = segment(x - l1 * std::cos(a1), y - l1 * std::sin(a1),
                                   x + 0.5 * l1 * std::cos(a1), y + 0.5 * l1 * std::sin(a1));
        const Segment s2 = segment(x + 5 * std::cos(a2), y + 5 * std::sin(a2),
                                   x + l2 * std::cos(a2), y + l2 * std::sin(a2));
        REQUIRE(intersect_lines(s1, s2, c));
        worst = std::fmax(worst, std::hypot(from_q16(c.x) - x, from_q16(c.y) - y));
    }
    // The inputs are rounded to 2^-16 px and 2^-32 turn; 0.01 px is far below a pixel.
    CHECK(worst < 0.01);
}

TEST_CASE("a rectangle's four lines give one quadrangle, corners anti-clockwise as seen",
          "[quad]") {
    // Lines in a scrambled order, plus one line at 45°, parallel (within 34°) to none.
    const auto s =
        sides_of(pt(10, 10), pt(110, 10), pt(110, 85), pt(10, 85));  // top, right, bottom, left
    std::vector<Segment> lines = {s[2], s[0], segment(200, 30, 260, 90), s[3], s[1]};
    const Found f = find(lines, 320, 240);
    REQUIRE(f.status == Status::ok);
    REQUIRE(f.quads.size() == 1);
    const Quad& q = f.quads[0];
    require_corner(q.corners[0], 10, 10);   // top-left
    require_corner(q.corners[1], 10, 85);   // bottom-left
    require_corner(q.corners[2], 110, 85);  // bottom-right
    require_corner(q.corners[3], 110, 10);  // top-right
    CHECK(shoelace2(q.corners) < 0);
    // Side i lies on: left (index 3), bottom (0), right (4), top (1).
    CHECK(q.lines[0] == 3);
    CHECK(q.lines[1] == 0);
    CHECK(q.lines[2] == 4);
    CHECK(q.lines[3] == 1);
    CHECK(q.score == q16_16::from_int(1));  // every side fully covered
}

TEST_CASE("a board turned 25° and seen in perspective keeps the corner order", "[quad]") {
    // A trapezoid-like board: top narrower than the bottom, turned clockwise on screen.
    const double c = std::cos(25 * ref::kPi / 180), s = std::sin(25 * ref::kPi / 180);
    const double raw[4][2] = {{-45, -35}, {-55, 35}, {55, 35}, {45, -35}};  // TL, BL, BR, TR
    Point16 v[4];
    for (int i = 0; i < 4; ++i)
        v[i] = pt(160 + raw[i][0] * c - raw[i][1] * s, 120 + raw[i][0] * s + raw[i][1] * c);
    const Found f = find(sides_of(v[0], v[1], v[2], v[3]), 320, 240);
    REQUIRE(f.quads.size() == 1);
    for (int i = 0; i < 4; ++i)
        require_corner(f.quads[0].corners[i], from_q16(v[i].x), from_q16(v[i].y), 0.01);
}

TEST_CASE("each rule turns down a candidate that breaks it", "[quad]") {
    SECTION("rule 1: a kite-like quadrangle with non-parallel opposite sides") {
        QuadParams p;
        p.parallel_tolerance = angle_from_deg(10);
        // Left side vertical, right side leaning 20°: no parallel pair for them.
        const Found f =
            find(sides_of(pt(50, 50), pt(50, 150), pt(200, 150), pt(164, 50)), 320, 240, p);
        CHECK(f.quads.empty());
        CHECK(f.stats.parallel_pairs == 1);  // only top and bottom
    }
    SECTION("rule 2: a parallelogram sheared 45°") {
        const Found f =
            find(sides_of(pt(50, 50), pt(150, 150), pt(300, 150), pt(200, 50)), 320, 240);
        CHECK(f.quads.empty());
        CHECK(f.stats.rejected_perpendicular == 1);
    }
    SECTION("rule 3: a rectangle whose lines cross outside the frame") {
        // Segments inside the frame, corners at x = -5.
        std::vector<Segment> lines = {segment(2, 50, 150, 50), segment(2, 150, 150, 150),
                                      segment(-5, 60, -5, 140), segment(150, 50, 150, 150)};
        const Found f = find(lines, 320, 240);
        CHECK(f.quads.empty());
        CHECK(f.stats.rejected_inside == 1);
    }
    SECTION("rule 4: a rectangle with a side below the minimum") {
        QuadParams p;
        p.min_side_length = q16_16::from_int(40);
        // 100 × 30: the pair 30 px apart passes the 20 px separation prefilter, rule 4 fails.
        const Found f =
            find(sides_of(pt(50, 50), pt(50, 80), pt(150, 80), pt(150, 50)), 320, 240, p);
        CHECK(f.quads.empty());
        CHECK(f.stats.rejected_sides == 1);
    }
    SECTION("rule 5: a 3:1 strip against a 4:3 display") {
        const Found f =
            find(sides_of(pt(20, 50), pt(20, 110), pt(200, 110), pt(200, 50)), 320, 240);
        CHECK(f.quads.empty());
        CHECK(f.stats.rejected_aspect == 1);
    }
    SECTION("support: a side whose line's segment lies beyond the corner") {
        auto s = sides_of(pt(50, 50), pt(50, 140), pt(170, 140), pt(170, 50));
        s[0] = segment(50, 150, 50, 230);  // the left line, but its segment is below the board
        const Found f = find(s, 320, 240);
        CHECK(f.quads.empty());
        CHECK(f.stats.rejected_support == 1);
    }
}

TEST_CASE("candidates are ranked by support and a full pair list says so", "[quad]") {
    // Two boards side by side; the left one's top line covers only half its side.
    auto a = sides_of(pt(20, 50), pt(20, 140), pt(140, 140), pt(140, 50));
    auto b = sides_of(pt(170, 60), pt(170, 150), pt(290, 150), pt(290, 60));
    a[3] = segment(20, 50, 80, 50);
    std::vector<Segment> lines = {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]};
    const Found f = find(lines, 320, 240, QuadParams{}, 64, 8);
    REQUIRE(f.status == Status::ok);
    REQUIRE(f.quads.size() >= 2);
    require_corner(f.quads[0].corners[0], 170, 60);  // the fully covered board first
    CHECK(f.quads[0].score == q16_16::from_int(1));
    for (size_t i = 1; i < f.quads.size(); ++i) CHECK(f.quads[i].score <= f.quads[i - 1].score);
    // (420 − 60) / 420 of the left board's perimeter is covered.
    bool left_found = false;
    for (const Quad& q : f.quads) {
        if (std::fabs(from_q16(q.corners[0].x) - 20) > 1e-3 ||
            std::fabs(from_q16(q.corners[0].y) - 50) > 1e-3 ||
            std::fabs(from_q16(q.corners[2].x) - 140) > 1e-3)
            continue;  // e.g. the left board's top and bottom with the right board's left side
        left_found = true;
        CHECK(std::fabs(from_q16(q.score) - 360.0 / 420) < 1e-4);
    }
    CHECK(left_found);

    const Found cut = find(lines, 320, 240, QuadParams{}, 1);
    CHECK(cut.status == Status::capacity_exceeded);
    CHECK(cut.stats.parallel_pairs == 1);
    CHECK(cut.stats.pairs_dropped > 0);
}

TEST_CASE("degenerate line sets give no quadrangle and no error", "[quad]") {
    CHECK(find({}, 320, 240).quads.empty());
    CHECK(find({segment(10, 10, 100, 10)}, 320, 240).quads.empty());
    // Four copies of one line.
    const Segment s = segment(10, 10, 100, 10);
    CHECK(find({s, s, s, s}, 320, 240).quads.empty());
    std::vector<LinePair> pairs(4);
    QuadLine geometry[1];
    Quad out[1];
    QuadStats stats;
    stats.quads = 7;
    CHECK(detect_quads(&s, 1, 0, 240, QuadParams{}, {pairs.data(), 4, geometry, out, 1}, &stats) ==
          Status::bad_size);
    CHECK(stats.quads == 0);
}

TEST_CASE("contrast: the board's inside is on every side's bright side", "[quad]") {
    // Rectangle (10, 10) – (110, 85). Normals (segment_reference.h): top θ 90° and left θ 0°
    // point into the board, right θ 0° and bottom θ 90° point out of it.
    auto lines =
        sides_of(pt(10, 10), pt(110, 10), pt(110, 85), pt(10, 85));  // top, right, bottom, left
    const int8_t inward[4] = {+1, -1, -1, +1};
    for (int i = 0; i < 4; ++i) lines[i].bright_side = inward[i];
    CHECK(find(lines, 320, 240).quads.size() == 1);

    auto mixed = lines;
    mixed[2].bright_side = +1;  // the bottom edge brighter outside: not a bright board
    const Found f = find(mixed, 320, 240);
    CHECK(f.quads.empty());
    // Top and bottom no longer face each other with their bright sides: not a parallel pair
    // of a bright board, so no candidate is formed (left and right still pair).
    CHECK(f.stats.parallel_pairs == 1);
    CHECK(f.stats.rejected_contrast == 0);
    QuadParams any;
    any.contrast = Contrast::any;
    CHECK(find(mixed, 320, 240, any).quads.size() == 1);

    auto dark = lines;
    for (Segment& s : dark) s.bright_side = static_cast<int8_t>(-s.bright_side);
    CHECK(find(dark, 320, 240).quads.empty());
    QuadParams dark_board;
    dark_board.contrast = Contrast::dark_board;
    CHECK(find(dark, 320, 240, dark_board).quads.size() == 1);
}

TEST_CASE("support: a side cut in two by an occluder counts both pieces", "[quad]") {
    // Left side x = 10 from y 10 to 85 (75 px): pieces 10..32 and 63..85, 22 px each (0.29).
    // Each side covered at least a third: one piece (0.29) is not enough, both (0.59) are.
    QuadParams third;
    third.min_side_coverage = q16_16::from_ratio(1, 3);
    auto s = sides_of(pt(10, 10), pt(110, 10), pt(110, 85), pt(10, 85));
    std::vector<Segment> one = {s[0], s[1], s[2], segment(10, 85, 10, 63)};
    const Found f = find(one, 320, 240, third);
    CHECK(f.quads.empty());
    CHECK(f.stats.rejected_support == 1);
    std::vector<Segment> both = one;
    both.push_back(segment(10, 32, 10, 10));
    const Found g = find(both, 320, 240, third);
    REQUIRE(g.quads.size() == 1);
    // (100 + 75 + 100 + 44) / 350 of the perimeter.
    CHECK(std::fabs(from_q16(g.quads[0].score) - 319.0 / 350) < 1e-4);
    // A parallel line 3 px to the side is another edge, not a piece of this one.
    std::vector<Segment> beside = one;
    beside.push_back(segment(13, 32, 13, 10));
    CHECK(find(beside, 320, 240, third).quads.empty());
}

TEST_CASE("support: a side's pieces count wherever they stand in the line list", "[quad]") {
    // The board of the case above, its left side in two pieces, behind 36 short pieces of one
    // 45° line (no parallel pairs among them, no line perpendicular to them: no candidate and
    // no pair taken from the board's): the pieces and the sides at
    // indices past 32, where detect_quads tests the lines one by one instead of reading the
    // collinear bits it keeps for the first 32. The score is the same (319 / 350) either way.
    QuadParams third;
    third.min_side_coverage = q16_16::from_ratio(1, 3);
    const auto s = sides_of(pt(10, 10), pt(110, 10), pt(110, 85), pt(10, 85));
    const Segment low = segment(10, 85, 10, 63), high = segment(10, 32, 10, 10);
    std::vector<Segment> filler;
    for (int k = 0; k < 36; ++k)
        filler.push_back(segment(160 + 4 * k, 10 + 4 * k, 162 + 4 * k, 12 + 4 * k));
    auto with = [&](std::vector<Segment> front, std::vector<Segment> back) {
        front.insert(front.end(), filler.begin(), filler.end());
        front.insert(front.end(), back.begin(), back.end());
        return front;
    };
    for (const auto& lines : {with({s[0], s[1], s[2], low, high}, {}),  // all before 32
                              with({s[0], s[1], s[2], low}, {high}),    // a piece past 32
                              with({high}, {s[0], s[1], s[2], low}),    // sides past 32
                              with({}, {s[0], s[1], s[2], low, high})}) {
        REQUIRE(lines.size() > 36);
        const Found f = find(lines, 320, 240, third);
        REQUIRE(f.quads.size() == 1);
        CHECK(std::fabs(from_q16(f.quads[0].score) - 319.0 / 350) < 1e-4);
    }
}

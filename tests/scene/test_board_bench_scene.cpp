// Board benchmark scenes: expectations from geometry worked by hand (axis-aligned and turned
// rectangles at tilt 0), from an independent reconstruction (the board plane's tilt from the
// vanishing points of the imaged sides and the focal length), and from pixel statistics
// next to the true sides — never from values the generator printed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "scene/board_bench_scene.h"
#include "scene/line_scene.h"

using qt::io::GreyImage;
using qt::scene::BoardBenchOptions;
using qt::scene::BoardBenchScene;
using qt::scene::make_board_bench_scene;
using qt::scene::Point2;

namespace {

const double kPi = 3.14159265358979323846;

// Σ x_i·y_{i+1} − x_{i+1}·y_i in image coordinates (y down): negative = anti-clockwise as seen.
double shoelace(const Point2 c[4]) {
    double s = 0;
    for (int i = 0; i < 4; ++i) s += c[i].x * c[(i + 1) % 4].y - c[(i + 1) % 4].x * c[i].y;
    return s;
}

double dist(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

int pixel(const GreyImage& img, double x, double y) {  // nearest pixel, clamped
    const int ix = std::min(img.width - 1, std::max(0, int(std::lround(x))));
    const int iy = std::min(img.height - 1, std::max(0, int(std::lround(y))));
    return img.at(ix, iy);
}

// Point at fraction t of side i, moved `depth` px inward (negative: outward).
Point2 side_point(const BoardBenchScene& s, int i, double t, double depth) {
    const Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
    const double len = dist(a, b), ex = (b.x - a.x) / len, ey = (b.y - a.y) / len;
    // Inward normal of a side of an anti-clockwise-as-seen quadrangle (y down): (ey, −ex).
    return {a.x + (b.x - a.x) * t + ey * depth, a.y + (b.y - a.y) * t - ex * depth};
}

// Mean of the 2·half + 1 pixels at 1 px steps along side i around side_point(i, t, depth).
double mean_along(const BoardBenchScene& s, int i, double t, double depth, int half) {
    const Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
    const double len = dist(a, b), ex = (b.x - a.x) / len, ey = (b.y - a.y) / len;
    const Point2 p = side_point(s, i, t, depth);
    double sum = 0;
    for (int k = -half; k <= half; ++k) sum += pixel(s.image, p.x + k * ex, p.y + k * ey);
    return sum / (2 * half + 1);
}

// Signed distance of q from the board outline, px: positive inside.
double board_distance(const BoardBenchScene& s, Point2 q) {
    double inside = 1e300;
    for (int i = 0; i < 4; ++i) {
        const Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
        inside =
            std::min(inside, ((b.y - a.y) * (q.x - a.x) - (b.x - a.x) * (q.y - a.y)) / dist(a, b));
    }
    if (inside >= 0) return inside;
    double out = 1e300;  // outside: distance to the nearest side segment
    for (int i = 0; i < 4; ++i) {
        const Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double t = std::min(
            1.0, std::max(0.0, ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy)));
        out = std::min(out, std::hypot(a.x + t * dx - q.x, a.y + t * dy - q.y));
    }
    return -out;
}

struct H3 {
    double x, y, z;
};
H3 hcross(H3 a, H3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Tilt from the image alone: the vanishing points of the two pairs of opposite sides,
// back-projected with the focal length and the principal point at the frame centre, are the
// board's two axis directions; their cross product is its normal; the tilt is the normal's
// angle from the optical axis, degrees.
double tilt_from_vanishing_points(const BoardBenchScene& s, int w, int h) {
    const H3 c[4] = {{s.corners[0].x, s.corners[0].y, 1},
                     {s.corners[1].x, s.corners[1].y, 1},
                     {s.corners[2].x, s.corners[2].y, 1},
                     {s.corners[3].x, s.corners[3].y, 1}};
    const H3 v1 = hcross(hcross(c[0], c[3]), hcross(c[1], c[2]));  // top and bottom sides
    const H3 v2 = hcross(hcross(c[0], c[1]), hcross(c[3], c[2]));  // left and right sides
    const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0, f = s.focal_px;
    const H3 d1{v1.x - cx * v1.z, v1.y - cy * v1.z, f * v1.z},
        d2{v2.x - cx * v2.z, v2.y - cy * v2.z, f * v2.z};
    const H3 n = hcross(d1, d2);
    return std::atan2(std::hypot(n.x, n.y), std::fabs(n.z)) * 180 / kPi;
}

BoardBenchOptions pinned(double tilt, double rotation, double scale, double aspect = 4.0 / 3) {
    BoardBenchOptions o;
    o.tilt_deg_min = o.tilt_deg_max = tilt;
    o.rotation_deg_min = o.rotation_deg_max = rotation;
    o.scale_min = o.scale_max = scale;
    o.aspect = aspect;
    return o;
}

}  // namespace

TEST_CASE("board bench: corners anti-clockwise as seen, inside the margin, at the drawn scale",
          "[board_bench_scene][slow]") {
    for (int occlude = 0; occlude < 2; ++occlude) {
        BoardBenchOptions o;
        o.occlude = occlude != 0;
        for (uint64_t seed = 1; seed <= 100; ++seed) {
            INFO("seed " << seed << " occlude " << occlude);
            const BoardBenchScene s = make_board_bench_scene(o, seed);
            REQUIRE(s.has_board);
            REQUIRE(s.image.width == 320);
            REQUIRE(s.image.height == 240);
            CHECK(shoelace(s.corners) < 0);
            for (int i = 0; i < 4; ++i) {  // convex: every turn anti-clockwise as seen
                const Point2 a = s.corners[i], b = s.corners[(i + 1) % 4],
                             c = s.corners[(i + 2) % 4];
                CHECK((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0);
                CHECK(s.corners[i].x >= 4);
                CHECK(s.corners[i].x <= 320 - 5);
                CHECK(s.corners[i].y >= 4);
                CHECK(s.corners[i].y <= 240 - 5);
            }
            // TL, BL, BR, TR of the display: with |rotation| <= 30° and tilt <= 40° the top-left
            // corner is left of the top-right one and above the bottom-left one, and so on.
            CHECK(s.corners[3].x > s.corners[0].x);
            CHECK(s.corners[2].x > s.corners[1].x);
            CHECK(s.corners[1].y > s.corners[0].y);
            CHECK(s.corners[2].y > s.corners[3].y);
            // Scale: the bounding box spans `scale` of the frame in its tighter direction.
            double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
            for (const Point2& p : s.corners) {
                x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
                y1 = std::max(y1, p.y);
            }
            CHECK(std::max((x1 - x0) / 320, (y1 - y0) / 240) == Approx(s.scale).margin(1e-9));
        }
    }
}

TEST_CASE("board bench: tilt 0, rotation 0 gives an axis-aligned rectangle of the aspect and scale",
          "[board_bench_scene]") {
    struct Case {
        double aspect, scale, width_px, height_px;
    };
    // 320×240 frame. 4:3 at scale 0.5: 160 × 120 (both ratios 0.5). 16:9 at 0.6: the width
    // governs, 0.6·320 = 192 px wide, 192·9/16 = 108 high. 1:1 at 0.5: the height governs,
    // 0.5·240 = 120 both ways. 1:2 at 0.8: 0.8·240 = 192 high, 96 wide.
    const Case cases[] = {{4.0 / 3, 0.5, 160, 120},
                          {16.0 / 9, 0.6, 192, 108},
                          {1, 0.5, 120, 120},
                          {0.5, 0.8, 96, 192}};
    for (const Case& c : cases) {
        for (uint64_t seed = 1; seed <= 10; ++seed) {
            INFO("aspect " << c.aspect << " seed " << seed);
            const BoardBenchScene s = make_board_bench_scene(pinned(0, 0, c.scale, c.aspect), seed);
            const Point2 tl = s.corners[0], bl = s.corners[1], br = s.corners[2], tr = s.corners[3];
            CHECK(s.tilt_deg == 0);
            CHECK(s.rotation_deg == 0);
            CHECK(bl.x == Approx(tl.x).margin(1e-9));
            CHECK(br.x == Approx(tr.x).margin(1e-9));
            CHECK(tr.y == Approx(tl.y).margin(1e-9));
            CHECK(br.y == Approx(bl.y).margin(1e-9));
            CHECK(tr.x - tl.x == Approx(c.width_px).margin(1e-9));
            CHECK(bl.y - tl.y == Approx(c.height_px).margin(1e-9));
        }
    }
}

TEST_CASE("board bench: rotation ±30° at tilt 0 turns the sides by 30° clockwise as seen",
          "[board_bench_scene]") {
    // A 4:3 rectangle of height L turned by 30°: bounding box (4/3·L·cos30 + L·sin30) wide and
    // (4/3·L·sin30 + L·cos30) high = L·(2/3 + √3/2) = 1.5327·L high and L·(2√3/3 + 1/2) =
    // 1.6547·L wide; in 320×240 the height ratio is the larger, so at scale 0.5 the box is 120
    // px high: L = 120 / (2/3 + √3/2) = 78.294 px, width 4/3·L = 104.392 px.
    const double r3 = std::sqrt(3.0);
    const double L = 120 / (2.0 / 3 + r3 / 2);
    for (int sign = -1; sign <= 1; sign += 2) {
        for (uint64_t seed = 1; seed <= 20; ++seed) {
            INFO("rotation " << sign * 30 << " seed " << seed);
            const BoardBenchScene s = make_board_bench_scene(pinned(0, sign * 30, 0.5), seed);
            const Point2 tl = s.corners[0], bl = s.corners[1], br = s.corners[2], tr = s.corners[3];
            // Top side TL -> TR along (cos 30°, ±sin 30°); left side TL -> BL along (∓sin 30°, cos
            // 30°).
            CHECK(tr.x - tl.x == Approx(4.0 / 3 * L * r3 / 2).margin(1e-9));
            CHECK(tr.y - tl.y == Approx(sign * 4.0 / 3 * L / 2).margin(1e-9));
            CHECK(bl.x - tl.x == Approx(-sign * L / 2).margin(1e-9));
            CHECK(bl.y - tl.y == Approx(L * r3 / 2).margin(1e-9));
            // Opposite sides equal: a parallelogram (no perspective at tilt 0).
            CHECK(br.x - bl.x == Approx(tr.x - tl.x).margin(1e-9));
            CHECK(br.y - bl.y == Approx(tr.y - tl.y).margin(1e-9));
            double y0 = 1e9, y1 = -1e9;
            for (const Point2& p : s.corners) y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
            CHECK(y1 - y0 == Approx(120).margin(1e-9));
        }
    }
}

TEST_CASE("board bench: the tilt seen through the vanishing points is the tilt recorded",
          "[board_bench_scene][slow]") {
    for (double focal : {0.0, 200.0, 600.0}) {
        BoardBenchOptions o;
        o.focal_px = focal;
        for (uint64_t seed = 1; seed <= 40; ++seed) {
            INFO("focal " << focal << " seed " << seed);
            const BoardBenchScene s = make_board_bench_scene(o, seed);
            CHECK(s.focal_px == (focal > 0 ? focal : 320));
            CHECK(tilt_from_vanishing_points(s, 320, 240) == Approx(s.tilt_deg).margin(1e-6));
        }
    }
}

TEST_CASE("board bench: pose, imaging and lighting stay in range and span it",
          "[board_bench_scene][slow]") {
    BoardBenchOptions o;
    o.noise_sigma_min = 2, o.noise_sigma_max = 8;
    o.blur_sigma_min = 0.5, o.blur_sigma_max = 1.5;
    double lo[6] = {1e9, 1e9, 1e9, 1e9, 1e9, 1e9}, hi[6] = {-1e9, -1e9, -1e9, -1e9, -1e9, -1e9};
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const BoardBenchScene s = make_board_bench_scene(o, seed);
        const double v[6] = {s.tilt_deg,    s.rotation_deg, s.scale,
                             s.noise_sigma, s.blur_sigma,   s.light_gain_min};
        for (int k = 0; k < 6; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
        CHECK(s.board_level >= 170);
        CHECK(s.board_level <= 240);
        CHECK(s.background_level <= s.board_level - 90);
    }
    // In range; 200 uniform draws leave gaps of about 1/200 of the range at each end.
    CHECK(lo[0] >= 0);
    CHECK(lo[0] < 2);
    CHECK(hi[0] <= 40);
    CHECK(hi[0] > 38);
    CHECK(lo[1] >= -30);
    CHECK(lo[1] < -28);
    CHECK(hi[1] <= 30);
    CHECK(hi[1] > 28);
    CHECK(lo[2] >= 0.15);
    CHECK(lo[2] < 0.17);
    CHECK(hi[2] <= 0.8);
    CHECK(hi[2] > 0.78);
    CHECK(lo[3] >= 2);
    CHECK(hi[3] <= 8);
    CHECK(lo[4] >= 0.5);
    CHECK(hi[4] <= 1.5);
    CHECK(lo[5] >= 0.55);
    CHECK(lo[5] < 0.6);
    CHECK(hi[5] <= 1);
    // Defaults pin the noise and blur.
    const BoardBenchScene d = make_board_bench_scene(BoardBenchOptions{}, 7);
    CHECK(d.noise_sigma == 4);
    CHECK(d.blur_sigma == 0.7);
}

TEST_CASE("board bench: the board is brighter just inside each side than just outside",
          "[board_bench_scene][slow]") {
    BoardBenchOptions o;
    for (uint64_t seed = 1; seed <= 100; ++seed) {
        const BoardBenchScene s = make_board_bench_scene(o, seed);
        for (int i = 0; i < 4; ++i) {
            INFO("seed " << seed << " side " << i);
            // 4 px either side of the midpoint, 5 pixels along the side: the board (>= 170,
            // >= 50 above any clutter, gain >= 0.55 locally alike on both sides) against
            // background, texture or clutter.
            CHECK(mean_along(s, i, 0.5, 4, 2) > mean_along(s, i, 0.5, -4, 2) + 10);
        }
    }
}

TEST_CASE("board bench: the occluder darkens part of exactly one side and no corner",
          "[board_bench_scene][slow]") {
    BoardBenchOptions o;
    o.occlude = true;
    int occluded = 0;
    for (uint64_t seed = 1; seed <= 100; ++seed) {
        INFO("seed " << seed);
        const BoardBenchScene s = make_board_bench_scene(o, seed);
        if (s.occluded_side < 0) continue;  // allowed only when every side is < 30 px
        ++occluded;
        REQUIRE(s.occluded_side <= 3);
        const int i = s.occluded_side;
        const double len = dist(s.corners[i], s.corners[(i + 1) % 4]);
        const double t0 = s.occluded_from, t1 = s.occluded_to;
        CHECK(t0 * len >= 10 - 1e-9);  // no corner covered
        CHECK((1 - t1) * len >= 10 - 1e-9);
        CHECK((t1 - t0) * len >= 10 - 1e-9);  // a real part ...
        CHECK(t1 - t0 <= 0.5 + 1e-12);        // ... of at most half the side
        // Inside, 2.5 px from the side: the covered middle is darker than the board 5 px
        // beyond either end of the covered part (the arm is >= 60 levels below the board).
        const double covered = mean_along(s, i, 0.5 * (t0 + t1), 2.5, 1);
        const double before = mean_along(s, i, t0 - 5 / len, 2.5, 0);
        const double after = mean_along(s, i, t1 + 5 / len, 2.5, 0);
        CHECK(covered < std::min(before, after) - 15);
        // The other three sides stay bright inside against outside at their midpoints.
        for (int j = 0; j < 4; ++j)
            if (j != i) CHECK(mean_along(s, j, 0.5, 4, 2) > mean_along(s, j, 0.5, -4, 2) + 10);
    }
    CHECK(occluded >= 95);
}

TEST_CASE("board bench: board-free frames share everything but the board",
          "[board_bench_scene][slow]") {
    BoardBenchOptions with, without;
    without.board = false;
    for (uint64_t seed = 1; seed <= 30; ++seed) {
        INFO("seed " << seed);
        const BoardBenchScene b = make_board_bench_scene(with, seed);
        const BoardBenchScene f = make_board_bench_scene(without, seed);
        CHECK_FALSE(f.has_board);
        CHECK(f.occluded_side == -1);
        CHECK(f.scale == 0);
        for (const Point2& p : f.corners) CHECK((p.x == 0 && p.y == 0));
        // Occlusion asked without a board: nothing more is drawn.
        BoardBenchOptions occ = without;
        occ.occlude = true;
        CHECK(make_board_bench_scene(occ, seed).image.pixels == f.image.pixels);
        // Away from the board (blur radius 3 px + anti-aliasing) the frames are identical;
        // inside it the board-free frame has no board.
        long differ = 0, n_inside = 0;
        double sum_board = 0, sum_free = 0;
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x) {
                const double d = board_distance(b, {double(x), double(y)});
                if (d < -5) differ += b.image.at(x, y) != f.image.at(x, y);
                if (d > 4) ++n_inside, sum_board += b.image.at(x, y), sum_free += f.image.at(x, y);
            }
        CHECK(differ == 0);
        REQUIRE(n_inside > 0);
        CHECK(sum_free / n_inside < sum_board / n_inside - 40);
    }
}

TEST_CASE("board bench: clutter has straight edges but is not board-like", "[board_bench_scene]") {
    BoardBenchOptions o;
    o.clutter_lines = 10, o.clutter_shapes = 20;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        const BoardBenchScene s = make_board_bench_scene(o, seed);
        REQUIRE(s.clutter_lines.size() == 10);
        REQUIRE(s.clutter_shapes.size() == 20);
        for (const auto& l : s.clutter_lines) {
            CHECK(dist(l.a, l.b) >= 0.08 * 240 - 1e-9);
            CHECK(dist(l.a, l.b) <= 0.6 * 240 + 1e-9);
        }
        for (const auto& v : s.clutter_shapes) {
            const int n = int(v.size());
            REQUIRE((n == 3 || n == 4));
            double min_angle = 180, min_side = 1e9, max_side = 0;
            for (int k = 0; k < n; ++k) {
                const Point2 a = v[(k + n - 1) % n], p = v[k], b = v[(k + 1) % n];
                const double cosine = ((a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y)) /
                                      (dist(a, p) * dist(b, p));
                min_angle = std::min(min_angle, std::acos(cosine) * 180 / kPi);
                min_side = std::min(min_side, dist(p, b)),
                max_side = std::max(max_side, dist(p, b));
            }
            if (n == 3) {
                CHECK(min_angle >= 12);
            } else {  // a thin bar or a strongly skewed quadrangle, never a near-rectangle
                INFO("min angle " << min_angle << " sides " << min_side << ".." << max_side);
                CHECK((max_side >= 5.9 * min_side || min_angle <= 40.001));
            }
        }
    }
}

TEST_CASE("board bench: uneven lighting between the drawn darkest gain and 1",
          "[board_bench_scene]") {
    // No noise and no blur, tilt 0: every pixel 1 px inside the rectangle is the board level
    // times the local gain, rounded.
    BoardBenchOptions o = pinned(0, 0, 0.6);
    o.noise_sigma_min = o.noise_sigma_max = 0;
    o.blur_sigma_min = o.blur_sigma_max = 0;
    o.light_gain_min = 1;
    const BoardBenchScene even = make_board_bench_scene(o, 3);
    CHECK(even.light_gain_min == 1);
    long n = 0, off = 0;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x)
            if (board_distance(even, {double(x), double(y)}) > 1)
                ++n, off += even.image.at(x, y) != even.board_level;
    CHECK(n > 10000);
    CHECK(off == 0);
    o.light_gain_min = 0.55;
    int spread_max = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        const BoardBenchScene s = make_board_bench_scene(o, seed);
        int lo = 255, hi = 0;
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                if (board_distance(s, {double(x), double(y)}) > 1)
                    lo = std::min(lo, int(s.image.at(x, y))),
                    hi = std::max(hi, int(s.image.at(x, y)));
        CHECK(hi <= s.board_level);
        CHECK(lo >= std::floor(s.board_level * s.light_gain_min + 0.5) - 1);
        spread_max = std::max(spread_max, hi - lo);
    }
    CHECK(spread_max > 40);  // some board crosses a good part of the light's range
}

TEST_CASE("line scene: illumination multiplies the composed scene by a ramp and a falloff",
          "[board_bench_scene][line_scene]") {
    qt::scene::SceneOptions o;
    o.width = 101, o.height = 51, o.background = 100;
    const GreyImage plain = qt::scene::LineScene(o).render();
    o.illumination.centre_x = 50, o.illumination.centre_y = 20;
    o.illumination.centre_gain = 0.9;
    o.illumination.ramp_x = 0.002;  // gain 0.8 at x = 0, 1.0 at x = 100 (on row 20)
    o.illumination.falloff = 1e-4;  // minus 0.01 at 10 px from (50, 20)
    const GreyImage lit = qt::scene::LineScene(o).render();
    CHECK(plain.at(0, 20) == 100);
    CHECK(lit.at(0, 20) == 55);    // 100·(0.9 − 0.1 − 0.25) = 55
    CHECK(lit.at(100, 20) == 75);  // 100·(0.9 + 0.1 − 0.25)
    CHECK(lit.at(50, 20) == 90);
    CHECK(lit.at(60, 20) == 91);  // 100·(0.9 + 0.02 − 0.01)
    CHECK(lit.at(50, 30) == 89);  // 100·(0.9 − 0.01)
    // A gain below 0 is clamped to 0.
    o.illumination.falloff = 1;
    CHECK(qt::scene::LineScene(o).render().at(0, 0) == 0);
    o.illumination.falloff = -1;
    CHECK_THROWS_AS(qt::scene::LineScene(o), std::invalid_argument);
}

TEST_CASE("board bench: deterministic in the seed", "[board_bench_scene]") {
    BoardBenchOptions o;
    o.occlude = true;
    o.noise_sigma_min = 1, o.noise_sigma_max = 6;
    const BoardBenchScene a = make_board_bench_scene(o, 42), b = make_board_bench_scene(o, 42);
    const BoardBenchScene c = make_board_bench_scene(o, 43);
    CHECK(a.image.pixels == b.image.pixels);
    for (int i = 0; i < 4; ++i)
        CHECK((a.corners[i].x == b.corners[i].x && a.corners[i].y == b.corners[i].y));
    CHECK(a.occluded_side == b.occluded_side);
    CHECK(a.image.pixels != c.image.pixels);
    CHECK(a.corners[0].x != c.corners[0].x);
}

TEST_CASE("board bench: options outside their ranges are refused", "[board_bench_scene]") {
    auto refused = [](void (*edit)(BoardBenchOptions&)) {
        BoardBenchOptions o;
        edit(o);
        CHECK_THROWS_AS(make_board_bench_scene(o, 1), std::invalid_argument);
    };
    refused([](BoardBenchOptions& o) { o.width = 10; });
    refused([](BoardBenchOptions& o) { o.aspect = 0; });
    refused([](BoardBenchOptions& o) { o.tilt_deg_max = 85; });
    refused([](BoardBenchOptions& o) { o.tilt_deg_min = 50; });  // above max
    refused([](BoardBenchOptions& o) { o.scale_max = 0.97; });  // (240 − 9) / 240 = 0.9625 at most
    refused([](BoardBenchOptions& o) { o.scale_min = 0; });
    refused([](BoardBenchOptions& o) { o.noise_sigma_min = -1; });
    refused([](BoardBenchOptions& o) { o.blur_sigma_max = 0.5; });  // below min 0.7
    refused([](BoardBenchOptions& o) { o.light_gain_min = 0; });
    refused([](BoardBenchOptions& o) { o.board_level_min = 100; });
    refused([](BoardBenchOptions& o) { o.clutter_lines = -1; });
    BoardBenchOptions largest;
    largest.scale_min = largest.scale_max = 0.96;  // just below (240 − 9) / 240: still fits
    CHECK(make_board_bench_scene(largest, 1).has_board);
}

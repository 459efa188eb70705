// Line/polygon scene generator: expectations worked out by hand from the geometry (pixel
// coverage fractions, areas) and from statistics, not from the renderer's code.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "scene/line_scene.h"

using qt::io::GreyImage;
using qt::scene::LineScene;
using qt::scene::Point2;
using qt::scene::SceneOptions;
using qt::scene::TrueSegment;

namespace {

SceneOptions plain(int w, int h, uint8_t background) {
    SceneOptions o;
    o.width = w;
    o.height = h;
    o.background = background;
    return o;
}

std::vector<Point2> rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Sum over the image of (v - bg) / (level - bg): the covered area in px^2.
double covered_area(const GreyImage& img, int bg, int level) {
    double sum = 0;
    for (uint8_t v : img.pixels) sum += double(v - bg) / (level - bg);
    return sum;
}

double length(const TrueSegment& s) { return std::hypot(s.b.x - s.a.x, s.b.y - s.a.y); }

bool inside_margin(Point2 p, const SceneOptions& o) {  // >= 4 px inside the outer pixel centres
    return p.x >= 4 && p.x <= o.width - 5 && p.y >= 4 && p.y <= o.height - 5;
}

// The polygons of random_polygon_scene's truth: runs of sides closing on their first vertex.
std::vector<std::vector<Point2>> chain_polygons(const std::vector<TrueSegment>& truth) {
    std::vector<std::vector<Point2>> polys;
    std::vector<Point2> cur;
    for (const TrueSegment& s : truth) {
        cur.push_back(s.a);
        if (s.b.x == cur[0].x && s.b.y == cur[0].y) {
            polys.push_back(cur);
            cur.clear();
        }
    }
    REQUIRE(cur.empty());
    return polys;
}

double cross(Point2 o, Point2 a, Point2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool strictly_inside_convex(const std::vector<Point2>& poly, Point2 p) {
    int pos = 0, neg = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const double c = cross(poly[i], poly[(i + 1) % poly.size()], p);
        pos += c > 0;
        neg += c < 0;
    }
    return pos == int(poly.size()) || neg == int(poly.size());
}

}  // namespace

TEST_CASE("scene: half-pixel rectangle edges give exact levels", "[scene]") {
    // Edges on pixel boundaries: pixels 11..50 × 21..60 fully covered, all others not at all.
    LineScene s(plain(80, 80, 60));
    s.add_polygon(rect(10.5, 20.5, 50.5, 60.5), 200);
    const GreyImage img = s.render();
    REQUIRE(img.width == 80);
    REQUIRE(img.height == 80);
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 80; ++x) {
            const bool in = x >= 11 && x <= 50 && y >= 21 && y <= 60;
            INFO("x " << x << " y " << y);
            REQUIRE(int(img.at(x, y)) == (in ? 200 : 60));
        }
    REQUIRE(s.truth().size() == 4);
    CHECK(s.truth()[0].a.x == 10.5);
    CHECK(s.truth()[0].b.x == 50.5);
    CHECK(s.truth()[3].b.y == 20.5);
}

TEST_CASE("scene: fractional coverage of edge and corner pixels", "[scene]") {
    // Rectangle x 10.25..50.0, y 20.0..60.75, level 220 on 60 (contrast 160):
    // column 10 covered 1/4 (+40), column 50 1/2 (+80), row 20 1/2, row 61 1/4;
    // corners (10,20) 1/8 -> 80, (50,20) 1/4 -> 100, (10,61) 1/16 -> 70, (50,61) 1/8 -> 80.
    LineScene s(plain(64, 72, 60));
    s.add_polygon(rect(10.25, 20.0, 50.0, 60.75), 220);
    const GreyImage img = s.render();
    auto fx = [](int x) { return x < 10 || x > 50 ? 0.0 : x == 10 ? 0.25 : x == 50 ? 0.5 : 1.0; };
    auto fy = [](int y) { return y < 20 || y > 61 ? 0.0 : y == 20 ? 0.5 : y == 61 ? 0.25 : 1.0; };
    for (int y = 0; y < 72; ++y)
        for (int x = 0; x < 64; ++x) {
            INFO("x " << x << " y " << y);
            REQUIRE(double(img.at(x, y)) == Approx(60 + 160 * fx(x) * fy(y)).margin(1));
        }
    CHECK(int(img.at(10, 61)) == Approx(70).margin(1));
    CHECK(covered_area(img, 60, 220) == Approx(39.75 * 40.75).margin(2));
}

TEST_CASE("scene: concave polygon and sloped triangle areas", "[scene]") {
    // L shape on half-pixel corners: area 50·20 + 20·30 = 1600 px^2, the notch stays background.
    LineScene l(plain(80, 80, 40));
    l.add_polygon(
        {{10.5, 10.5}, {60.5, 10.5}, {60.5, 30.5}, {30.5, 30.5}, {30.5, 60.5}, {10.5, 60.5}}, 240);
    const GreyImage li = l.render();
    CHECK(covered_area(li, 40, 240) == Approx(1600).margin(0.01));
    CHECK(int(li.at(45, 45)) == 40);
    CHECK(int(li.at(20, 45)) == 240);
    CHECK(int(li.at(45, 20)) == 240);
    CHECK(l.truth().size() == 6);

    // Triangle with arbitrary vertices: shoelace area, within rounding and sampling error.
    const std::vector<Point2> t{{10.3, 10.7}, {70.1, 15.2}, {30.6, 55.9}};
    const double area = 0.5 * std::fabs(cross(t[0], t[1], t[2]));
    LineScene tri(plain(80, 80, 40));
    tri.add_polygon(t, 200);
    CHECK(covered_area(tri.render(), 40, 200) == Approx(area).epsilon(0.005));
}

TEST_CASE("scene: line of width 2 covers its rectangle", "[scene]") {
    // Horizontal line y = 50 from x = 20 to 100, width 2: y 49..51 covered, so row 50 full,
    // rows 49 and 51 half; column 20 (x 19.5..20.5) and column 100 half.
    LineScene s(plain(120, 100, 60));
    s.add_line({20, 50}, {100, 50}, 2, 200);
    const GreyImage img = s.render();
    for (int x = 21; x <= 99; ++x) {
        INFO("x " << x);
        REQUIRE(int(img.at(x, 50)) == 200);
        REQUIRE(int(img.at(x, 49)) == 130);
        REQUIRE(int(img.at(x, 51)) == 130);
        REQUIRE(int(img.at(x, 48)) == 60);
        REQUIRE(int(img.at(x, 52)) == 60);
    }
    CHECK(int(img.at(20, 50)) == 130);
    CHECK(int(img.at(100, 50)) == 130);
    CHECK(int(img.at(20, 49)) == 95);  // quarter
    CHECK(int(img.at(19, 50)) == 60);
    CHECK(int(img.at(101, 50)) == 60);
    REQUIRE(s.truth().size() == 1);
    CHECK(s.truth()[0].a.x == 20);
    CHECK(s.truth()[0].b.x == 100);

    // A sloped line of width 3: covered area = length · width.
    LineScene d(plain(160, 120, 60));
    d.add_line({20.3, 30.1}, {140.7, 90.4}, 3, 180);
    CHECK(covered_area(d.render(), 60, 180) == Approx(std::hypot(120.4, 60.3) * 3).epsilon(0.005));
}

TEST_CASE("scene: noise on a flat frame has mean 0 and the requested sigma", "[scene]") {
    for (double sigma : {3.0, 8.0, 20.0}) {
        SceneOptions o = plain(320, 240, 128);
        o.noise_sigma = sigma;
        o.seed = 11;
        const GreyImage img = LineScene(o).render();
        double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
        for (uint8_t v : img.pixels) m1 += v;
        m1 /= img.pixels.size();
        for (uint8_t v : img.pixels) {
            const double d = v - m1;
            m2 += d * d, m3 += d * d * d, m4 += d * d * d * d;
        }
        m2 /= img.pixels.size(), m3 /= img.pixels.size(), m4 /= img.pixels.size();
        const double sd = std::sqrt(m2);
        INFO("sigma " << sigma << " mean " << m1 << " sd " << sd);
        CHECK(m1 == Approx(128).margin(0.1));
        CHECK(sd == Approx(sigma).epsilon(0.03));         // rounding adds 1/12 grey^2
        CHECK(std::fabs(m3 / (m2 * sd)) < 0.05);          // skewness of a Gaussian: 0
        CHECK(m4 / (m2 * m2) == Approx(3).margin(0.15));  // kurtosis of a Gaussian: 3
    }
}

TEST_CASE("scene: blur keeps flat levels and the mean, and softens a step", "[scene]") {
    SceneOptions flat = plain(64, 48, 77);
    flat.blur_sigma = 2;
    for (uint8_t v : LineScene(flat).render().pixels) REQUIRE(int(v) == 77);

    // Vertical step at x = 159.5 (pixel boundary), 60 -> 200, with and without sigma 1.5 px.
    SceneOptions o = plain(320, 60, 60);
    LineScene sharp(o);
    sharp.add_polygon(rect(159.5, -10, 400, 100), 200);
    o.blur_sigma = 1.5;
    LineScene soft(o);
    soft.add_polygon(rect(159.5, -10, 400, 100), 200);
    const GreyImage a = sharp.render(), b = soft.render();
    double mean_a = 0, mean_b = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) mean_a += a.pixels[i], mean_b += b.pixels[i];
    CHECK(mean_b / b.pixels.size() == Approx(mean_a / a.pixels.size()).margin(0.05));
    const int y = 30;
    int max_a = 0, max_b = 0;
    for (int x = 0; x + 1 < 320; ++x) {
        REQUIRE(b.at(x + 1, y) >= b.at(x, y));  // still monotone
        max_a = std::max(max_a, a.at(x + 1, y) - a.at(x, y));
        max_b = std::max(max_b, b.at(x + 1, y) - b.at(x, y));
    }
    CHECK(max_a == 140);
    // Steepest step of a Gaussian-blurred edge: 140 / (sigma sqrt(2 pi)) = 37.2 grey levels.
    CHECK(max_b == Approx(37.2).margin(2));
    CHECK(int(b.at(150, y)) == 60);  // beyond the kernel radius: untouched
    CHECK(int(b.at(170, y)) == 200);
}

TEST_CASE("scene: frames are identical for a seed and differ between seeds", "[scene]") {
    SceneOptions o;
    o.noise_sigma = 5, o.blur_sigma = 1, o.clutter_blobs = 20, o.clutter_texture = 20, o.seed = 7;
    const GreyImage a = qt::scene::random_polygon_scene(o, 3, 25).render();
    const LineScene again = qt::scene::random_polygon_scene(o, 3, 25);
    CHECK(again.render().pixels == a.pixels);
    CHECK(again.render().pixels == a.pixels);
    o.seed = 8;
    const LineScene other = qt::scene::random_polygon_scene(o, 3, 25);
    CHECK(other.render().pixels != a.pixels);
    CHECK(other.truth()[0].a.x != again.truth()[0].a.x);

    SceneOptions l;
    l.noise_sigma = 3, l.seed = 5;
    CHECK(qt::scene::random_line_scene(l, 6, 30, 120).render().pixels ==
          qt::scene::random_line_scene(l, 6, 30, 120).render().pixels);
}

TEST_CASE("scene: random polygons are inside, long-sided, convex and contrasting", "[scene]") {
    int triangles = 0, quads = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        SceneOptions o;
        o.seed = seed;
        const LineScene s = qt::scene::random_polygon_scene(o, 4, 20);
        INFO("seed " << seed);
        for (const TrueSegment& t : s.truth()) {
            REQUIRE(inside_margin(t.a, o));
            REQUIRE(inside_margin(t.b, o));
            REQUIRE(length(t) >= 20);
        }
        const auto polys = chain_polygons(s.truth());
        REQUIRE(polys.size() == 4);
        const GreyImage img = s.render();
        for (std::size_t i = 0; i < polys.size(); ++i) {
            const auto& p = polys[i];
            REQUIRE((p.size() == 3 || p.size() == 4));
            (p.size() == 3 ? triangles : quads)++;
            Point2 c{0, 0};
            for (Point2 v : p) c.x += v.x / p.size(), c.y += v.y / p.size();
            REQUIRE(strictly_inside_convex(p, c));  // convex with a consistent winding
            for (std::size_t j = 0; j < polys.size(); ++j)
                for (Point2 v : polys[j])
                    REQUIRE((j == i || !strictly_inside_convex(p, v)));  // no overlap
            const int level = img.at(int(std::lround(c.x)), int(std::lround(c.y)));
            REQUIRE(std::abs(level - 60) >= 60);
        }
    }
    CHECK(triangles > 10);
    CHECK(quads > 10);
}

TEST_CASE("scene: random lines have the requested lengths inside the frame", "[scene]") {
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        SceneOptions o;
        o.seed = seed;
        const LineScene s = qt::scene::random_line_scene(o, 10, 40, 150);
        INFO("seed " << seed);
        REQUIRE(s.truth().size() == 10);
        for (const TrueSegment& t : s.truth()) {
            REQUIRE(inside_margin(t.a, o));
            REQUIRE(inside_margin(t.b, o));
            REQUIRE(length(t) >= 40);
            REQUIRE(length(t) <= 150);
        }
    }
}

TEST_CASE("scene: impossible requests are refused", "[scene]") {
    LineScene s(plain(32, 32, 60));
    CHECK_THROWS_AS(s.add_polygon({{1, 1}, {5, 5}}, 200), std::invalid_argument);
    CHECK_THROWS_AS(s.add_line({3, 3}, {3, 3}, 2, 200), std::invalid_argument);
    CHECK_THROWS_AS(qt::scene::random_polygon_scene(SceneOptions{}, 1, 200), std::invalid_argument);
    CHECK_THROWS_AS(qt::scene::random_line_scene(SceneOptions{}, 1, 500, 600),
                    std::invalid_argument);
    SceneOptions bad;
    bad.noise_sigma = -1;
    CHECK_THROWS_AS(LineScene(bad), std::invalid_argument);
}

// Accuracy of the lines stage on generated scenes with known geometry (fixed seeds): truth
// segments of at least 2 × min_line_length found within 1° and 2 px at each end, at Gaussian
// noise σ = 5 grey levels. The bench's table (bash bench.sh lines-host) runs more scenes.
#include <catch2/catch.hpp>
#include <cmath>

#include "lines/line_detector.h"
#include "scene/line_match.h"

using namespace qt;

namespace {

LineDetectorQvga g_det;

scene::MatchResult score(const scene::LineScene& s) {
    const io::GreyImage img = s.render();
    REQUIRE(g_det.begin_frame(320, 240, LineParams{}) == Status::ok);
    for (int y = 0; y < 240; ++y) REQUIRE(g_det.push_row(img.row(y), 320) == Status::ok);
    REQUIRE(g_det.finish() == Status::ok);
    std::vector<scene::DetectedLine> d;
    for (uint16_t i = 0; i < g_det.line_count(); ++i) {
        const Segment& l = g_det.lines()[i];
        d.push_back(
            {{l.x1.raw / 65536.0, l.y1.raw / 65536.0}, {l.x2.raw / 65536.0, l.y2.raw / 65536.0}});
    }
    scene::MatchRule rule;
    rule.min_length = 2.0 * LineParams{}.hough.min_line_length;
    return scene::match_lines(s.truth(), d, rule);
}

struct Totals {
    int scored = 0, found = 0, false_positives = 0;
    void add(const scene::MatchResult& r) {
        scored += r.scored;
        found += r.found;
        false_positives += r.false_positives;
    }
};

scene::SceneOptions noisy(uint64_t seed) {
    scene::SceneOptions o;
    o.noise_sigma = 5;
    o.blur_sigma = 0.7;
    o.seed = seed;
    return o;
}

}  // namespace

TEST_CASE("polygon edges at noise 5: every side found, no false positives", "[accuracy]") {
    // Quadrangles and triangles with corners of 60° or more (board-like), then with corners of
    // any angle. The bench's table (bash bench.sh lines-host --scenes 1000) runs seeds 1..1000
    // of both kinds; these are others.
    for (const double min_corner_deg : {60.0, 0.0}) {
        Totals t;
        constexpr int kScenes = 50;
        for (int i = 0; i < kScenes; ++i)
            t.add(score(scene::random_polygon_scene(noisy(1000 + i), 2, 40, min_corner_deg)));
        INFO("corners >= " << min_corner_deg << " deg: found " << t.found << " of " << t.scored
                           << ", false positives " << t.false_positives);
        REQUIRE(t.scored >= 300);
        REQUIRE(t.found == t.scored);
        REQUIRE(t.false_positives == 0);
    }
}

TEST_CASE("scenes that once lost a side keep every side", "[accuracy]") {
    // Bench seeds (bash bench.sh lines-host), each of which lost one side to a mechanism now
    // in place; taking the mechanism out loses the side again.
    struct Case {
        uint64_t seed;
        double noise, min_corner_deg;
        const char* why;
    };
    const Case cases[] = {
        {849, 5, 60,
         "clustering: sides of two shapes 1 deg apart, 4.5 px beside each other across a 12 px "
         "gap, merged (on one line)"},
        {122, 5, 0,
         "clustering: sides of two shapes 3 deg apart, 8 px beside each other across a 14 px gap, "
         "merged (on one line)"},
        {24, 5, 60,
         "PPHT: a seed bin 18 deg off; way 0 left the line before any refit (walked again)"},
        {898, 0, 60,
         "PPHT: a clean 42 deg staircase; the nearer of two points per column biased the fit (all "
         "fitted)"},
        {20, 5, 60, "PPHT: one noise pixel 4 px past a corner carried the end (runs after gaps)"},
        {167, 5, 60, "PPHT: two noise pixels 3 px past a corner carried the end (runs after gaps)"},
    };
    for (const Case& c : cases) {
        scene::SceneOptions o = noisy(c.seed);
        o.noise_sigma = c.noise;
        o.blur_sigma = c.noise > 0 ? 0.7 : 0;
        const scene::MatchResult r = score(scene::random_polygon_scene(o, 2, 40, c.min_corner_deg));
        INFO("seed " << c.seed << ": " << c.why << "; found " << r.found << " of " << r.scored);
        REQUIRE(r.found == r.scored);
    }
}

TEST_CASE("drawn 2-px lines at noise 5: both sides merge into the centre line",
          "[accuracy][slow]") {
    // The false positives of these scenes move by about a tenth with PPHT's visiting order alone
    // (159 to 196 on 400 scenes over the orders tried), so the bound is on 200 scenes rather
    // than on one order's luck with 50.
    Totals t;
    constexpr int kScenes = 200;
    for (int i = 0; i < kScenes; ++i)
        t.add(score(scene::random_line_scene(noisy(2000 + i), 4, 40, 150)));
    INFO("found " << t.found << " of " << t.scored << ", false positives " << t.false_positives);
    REQUIRE(t.scored == 4 * kScenes);
    REQUIRE(t.found >= t.scored * 90 / 100);
    REQUIRE(t.false_positives <= kScenes / 2);
}

TEST_CASE("a noiseless axis-aligned rectangle is found to a fifth of a pixel", "[accuracy]") {
    scene::SceneOptions o;
    scene::LineScene s(o);
    s.add_polygon({{90.3, 70.2}, {230.3, 70.2}, {230.3, 170.2}, {90.3, 170.2}}, 200);
    const scene::MatchResult r = score(s);
    REQUIRE(r.found == 4);
    REQUIRE(r.false_positives == 0);
    REQUIRE(r.worst_angle_deg < 0.1);
    // Ends joined at the corners: within a fifth of a pixel of them.
    REQUIRE(r.worst_endpoint_px < 0.2);
    for (uint16_t i = 0; i < g_det.line_count(); ++i) {
        const double rho = g_det.lines()[i].rho.raw / 65536.0;
        const bool on_side = std::fabs(rho - 70.2) < 0.2 || std::fabs(rho - 170.2) < 0.2 ||
                             std::fabs(rho - 90.3) < 0.2 || std::fabs(rho - 230.3) < 0.2;
        INFO("rho " << rho);
        REQUIRE(on_side);
    }
}

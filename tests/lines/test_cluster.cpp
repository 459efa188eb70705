// Clustering: the paper's |Ci - Cj| measure, the orientation test it needs near the origin,
// the gap test, and the refit from all members.
#include <catch2/catch.hpp>
#include <cmath>

#include "lines/line_cluster.h"
#include "lines/line_fit.h"

using namespace qt;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A segment from (x1, y1) to (x2, y2) in pixels with `points` points, through the same
// make_segment as PPHT (so rho, theta and C are consistent).
Segment seg(double x1, double y1, double x2, double y2, uint16_t points) {
    Moments m;
    const int n = 64;
    for (int i = 0; i <= n; ++i)
        m.add(static_cast<int32_t>(std::lround((x1 + (x2 - x1) * i / n) * 32)),
              static_cast<int32_t>(std::lround((y1 + (y2 - y1) * i / n) * 32)));
    FittedLine line;
    REQUIRE(fit_line(m, 0, 0, line));
    auto px = [](double v) { return q16_16::from_raw(std::lround(v * 65536)); };
    q16_16 t1 = along(line, px(x1), px(y1)), t2 = along(line, px(x2), px(y2));
    if (t2 < t1) std::swap(t1, t2);
    return make_segment(line, t1, t2, points);
}

double deg(angle_t a) { return a / 4294967296.0 * 360.0; }
double px(q16_16 v) { return v.raw / 65536.0; }

struct Run {
    Segment out[8];
    uint16_t count = 0;
    ClusterStats stats;
};

Run cluster(std::initializer_list<Segment> in, const ClusterParams& p = ClusterParams{}) {
    Run r;
    Segment segs[8];
    uint8_t scratch[8];
    uint16_t n = 0;
    for (const Segment& s : in) segs[n++] = s;
    REQUIRE(cluster_segments(segs, n, p, scratch, r.out, 8, &r.count, &r.stats) == Status::ok);
    return r;
}

}  // namespace

TEST_CASE("make_segment gives rho, theta and C of a hand-worked line", "[cluster]") {
    // The line y = 10 (normal pointing down, +y): rho 10, theta 90°, C = (0, 10).
    const Segment s = seg(5, 10, 45, 10, 40);
    REQUIRE(px(s.rho) == Approx(10).margin(1e-3));
    REQUIRE(deg(s.theta) == Approx(90).margin(1e-4));
    REQUIRE(px(s.cx) == Approx(0).margin(1e-3));
    REQUIRE(px(s.cy) == Approx(10).margin(1e-3));
    // x + y = 20: rho 20/√2, theta 45°, C = (10, 10).
    const Segment d = seg(0, 20, 20, 0, 40);
    REQUIRE(px(d.rho) == Approx(20 / std::sqrt(2.0)).margin(1e-3));
    REQUIRE(deg(d.theta) == Approx(45).margin(1e-4));
    REQUIRE(px(d.cx) == Approx(10).margin(1e-3));
    REQUIRE(px(d.cy) == Approx(10).margin(1e-3));
}

TEST_CASE("duplicates of one edge merge into one refitted line spanning them", "[cluster]") {
    // Two pieces of nearly one edge, 0.5 px apart, overlapping: 70 points on y = 50 from
    // x = 10 to 80, 30 points on y = 50.5 from 60 to 120. Reference: a double-precision total
    // least-squares fit of those 100 points spread evenly along their pieces.
    const Run r = cluster({seg(10, 50, 80, 50, 70), seg(60, 50.5, 120, 50.5, 30)});
    REQUIRE(r.count == 1);
    const Segment& l = r.out[0];
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, n = 0;
    auto add_piece = [&](double x1, double x2, double y, int count) {
        for (int i = 0; i < count; ++i) {
            const double x = x1 + (x2 - x1) * (i + 0.5) / count;
            sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, n += 1;
        }
    };
    add_piece(10, 80, 50, 70);
    add_piece(60, 120, 50.5, 30);
    const double mx = sx / n, my = sy / n;
    const double cxx = sxx / n - mx * mx, cyy = syy / n - my * my, cxy = sxy / n - mx * my;
    const double phi = 0.5 * std::atan2(2 * cxy, cxx - cyy);  // direction of the line
    const double nx = -std::sin(phi), ny = std::cos(phi);
    double rho = mx * nx + my * ny, theta = std::atan2(ny, nx) * 180 / kPi;
    if (rho < 0) rho = -rho, theta += 180;
    REQUIRE(px(l.rho) == Approx(rho).margin(0.01));
    REQUIRE(deg(l.theta) == Approx(std::fmod(theta + 360, 360)).margin(0.01));
    REQUIRE(std::min(px(l.x1), px(l.x2)) == Approx(10).margin(0.05));
    REQUIRE(std::max(px(l.x1), px(l.x2)) == Approx(120).margin(0.05));
    REQUIRE(l.points == 100);
}

TEST_CASE("two lines through the origin share C = (0, 0) but do not merge", "[cluster]") {
    const Segment a = seg(-40, 0, 40, 0, 50);                                       // y = 0
    const Segment b = seg(-30, -30 * std::sqrt(3.0), 30, 30 * std::sqrt(3.0), 50);  // 60°
    REQUIRE(std::hypot(px(a.cx) - px(b.cx), px(a.cy) - px(b.cy)) < 0.01);
    REQUIRE(cluster({a, b}).count == 2);
    // With the orientation and the on-one-line tests switched off, the paper's measure alone
    // merges them.
    ClusterParams paper_only;
    paper_only.max_angle = kAngleQuarterTurn;
    paper_only.offset = q16_16::from_int(1000);
    REQUIRE(cluster({a, b}, paper_only).count == 1);
}

TEST_CASE(
    "near the origin, sides of two shapes 4 degrees apart pass S and the angle test but do not "
    "merge",
    "[cluster]") {
    // Hand-worked (a generated scene had this pair): a runs at 53.4°, b at 49.5°, overlapping
    // along their direction. Their lines pass about 31 px from the origin, so C moves only
    // rho·Δθ ≈ 2 px with the 3.9° between them: |Ca − Cb| < 3 px, within the paper's 6 px.
    // But b is the longer (64.5 px against 62.2), and a's ends lie 14.6 and 18.8 px beside
    // b's line.
    const Segment a = seg(133.16, 128.92, 170.18, 178.85, 50);
    const Segment b = seg(183.96, 166.05, 225.84, 215.15, 50);
    REQUIRE(std::hypot(px(a.cx) - px(b.cx), px(a.cy) - px(b.cy)) < 3.0);
    REQUIRE(cluster({a, b}).count == 2);
    ClusterParams p;
    p.offset = q16_16::from_int(19);  // both of a's ends within reach of b's line
    REQUIRE(cluster({a, b}, p).count == 1);
    p.offset = q16_16::from_int(18);  // one end beyond it
    REQUIRE(cluster({a, b}, p).count == 2);
}

TEST_CASE("collinear segments merge across a small gap, not across a large one", "[cluster]") {
    REQUIRE(cluster({seg(10, 30, 60, 30, 50), seg(70, 30, 120, 30, 50)}).count == 1);   // gap 10
    REQUIRE(cluster({seg(10, 30, 60, 30, 50), seg(100, 30, 150, 30, 50)}).count == 2);  // gap 40
}

TEST_CASE("the merged line is refitted from every member, not the longest one", "[cluster]") {
    // Three pieces of nearly one edge at -1°, 0° and +1.5°, the longest at 0°.
    auto piece = [](double x0, double len, double angle_deg, uint16_t pts) {
        const double a = angle_deg * kPi / 180.0;
        return seg(x0, 100, x0 + len * std::cos(a), 100 + len * std::sin(a), pts);
    };
    const Run r = cluster({piece(0, 100, 0, 100), piece(20, 60, -1, 60), piece(40, 60, 1.5, 60)});
    REQUIRE(r.count == 1);
    const double merged = std::fmod(deg(r.out[0].theta) + 360.0, 180.0);
    REQUIRE(merged != Approx(90.0).margin(0.01));  // not simply the longest member's normal
    REQUIRE(merged > 89.0);
    REQUIRE(merged < 91.5);
}

TEST_CASE("cluster output capacity is reported", "[cluster]") {
    Segment segs[3] = {seg(0, 0, 50, 0, 10), seg(0, 40, 50, 40, 10), seg(0, 80, 50, 80, 10)};
    Segment out[2];
    uint8_t scratch[3];
    uint16_t count = 0;
    ClusterStats stats;
    REQUIRE(cluster_segments(segs, 3, ClusterParams{}, scratch, out, 2, &count, &stats) ==
            Status::ok);
    REQUIRE(count == 2);
    REQUIRE(stats.clusters_dropped == 1);
    // 179° and 1° are 2° apart modulo 180° (each conversion rounds by up to half a unit).
    const angle_t d = orientation_difference(angle_from_deg(179), angle_from_deg(1));
    REQUIRE(d - angle_from_deg(2) + 1u <= 2u);
    REQUIRE(orientation_difference(angle_from_deg(10), angle_from_deg(190)) == 0u);
}

TEST_CASE("line ends near a corner move to the intersection, others stay", "[cluster]") {
    // The sides y = 50 (x from 12 to 100) and x = 10 (y from 52 to 120) of a corner at (10, 50):
    // both ends 2 px short of it. A third line, parallel to the first, stays as it is.
    Segment lines[3] = {seg(12, 50, 100, 50, 80), seg(10, 52, 10, 120, 60),
                        seg(12, 60, 100, 60, 80)};
    CornerCandidate scratch[6];
    const uint16_t moved = join_corners(lines, 3, CornerParams{}, scratch);
    // The third line's end at (12, 60) is 2 px from the second line, but the second line's
    // end (10, 52) is 8 px from their crossing (10, 60): not a corner of both.
    REQUIRE(moved == 2);
    REQUIRE(px(lines[0].x1) == Approx(10).margin(0.01));
    REQUIRE(px(lines[0].y1) == Approx(50).margin(0.01));
    REQUIRE(px(lines[1].x1) == Approx(10).margin(0.01));
    REQUIRE(px(lines[1].y1) == Approx(50).margin(0.01));
    REQUIRE(px(lines[2].x1) == Approx(12).margin(0.01));
    REQUIRE(px(lines[0].x2) == Approx(100).margin(0.01));  // far ends untouched
    REQUIRE(px(lines[1].y2) == Approx(120).margin(0.01));
    // Ends 5 px short are beyond the default reach of 3 px.
    Segment far[2] = {seg(15, 50, 100, 50, 80), seg(10, 55, 10, 120, 60)};
    REQUIRE(join_corners(far, 2, CornerParams{}, scratch) == 0);
}

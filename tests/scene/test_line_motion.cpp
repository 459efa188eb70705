// the Quadrangle Detection paper §3 bench data and score (platform/scene/line_motion.h): the
// overlap ratio on hand-worked cases, the motion generators' geometry, and the acceptance
// checks for the turn model on Experiments 1 and 2.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "scene/line_motion.h"
#include "support/segment_reference.h"

using namespace qt;
using qt::ref::segment;
namespace sc = qt::scene;

namespace {

// The tracked line through (x1, y1) and (x2, y2), built independently of line_motion.
Segment tracked(double x1, double y1, double x2, double y2) { return segment(x1, y1, x2, y2); }

double midpoint_dist(const sc::GtSegment& a, const sc::GtSegment& b) {
    return std::hypot((a.x1 + a.x2 - b.x1 - b.x2) / 2, (a.y1 + a.y2 - b.y1 - b.y2) / 2);
}

double length(const sc::GtSegment& s) { return std::hypot(s.x2 - s.x1, s.y2 - s.y1); }

// Distance, px, from p to the infinite line through s.
double line_dist(const sc::GtSegment& s, sc::Point2 p) {
    const double dx = s.x2 - s.x1, dy = s.y2 - s.y1;
    return std::fabs((p.x - s.x1) * dy - (p.y - s.y1) * dx) / std::hypot(dx, dy);
}

LineTrackerParams tracker(LineModel model, int filters = 3) {
    LineTrackerParams p = default_line_tracker_params(320, 240);
    p.model = model;
    p.filters = static_cast<uint8_t>(filters);
    return p;
}

}  // namespace

TEST_CASE("overlap: the tracked line on the truth scores 1", "[line_motion]") {
    // Along the major axis every drawn pixel is the line's point rounded in the minor axis only (<=
    // 0.5 px off the line), and the drawn columns reach at most 0.5 px past each end, so every
    // pixel lies within sqrt(0.5² + 0.5²) ≈ 0.71 px of the segment: inside the 1 px half-band.
    const sc::GtSegment shallow{20.3, 40.7, 140.2, 95.1}, steep{200.4, 10.2, 170.9, 190.6};
    CHECK(sc::overlap_ratio(shallow, tracked(20.3, 40.7, 140.2, 95.1)) == 1.0);
    CHECK(sc::overlap_ratio(steep, tracked(200.4, 10.2, 170.9, 190.6)) == 1.0);
}

TEST_CASE("overlap: a parallel line 3 px away scores 0", "[line_motion]") {
    // Horizontal truth y = 100, x in [10, 50]; tracked y = 103: every drawn pixel is on row 103,
    // 3 px from the truth, beyond the half-band of 1 px.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(0, 103, 300, 103)) == 0.0);
    // Diagonal truth; the tracked line moved 3 px along the normal (1, −1)/√2: pixels lie at
    // least 3 − 0.5 = 2.5 px from the truth.
    const double s = 3 / std::sqrt(2.0);
    CHECK(sc::overlap_ratio({10, 10, 110, 110}, tracked(10 + s, 10 - s, 110 + s, 110 - s)) == 0.0);
}

TEST_CASE("overlap: a line 0.9 px off still lies in the 2 px band", "[line_motion]") {
    // Truth y = 100, x in [10, 50]; tracked y = 100.9 rounds to row 101, 1 px from the truth:
    // inside (the half-band of 1 px is inclusive). All 41 columns 10..50 count: 41 / 41.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(0, 100.9, 300, 100.9)) == 1.0);
    // 1.6 px off rounds to row 102, 2 px away: nothing inside.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(0, 101.6, 300, 101.6)) == 0.0);
}

TEST_CASE("overlap: a tilted line leaves the band after a known number of pixels",
          "[line_motion]") {
    // Truth y = 100, x in [10, 50]. Tracked: y = 100.05 + (x − 10) / 10 (through (10, 100.05)
    // and (110, 110.05)). The truth's ends project onto it at x = 10 − 0.5/101 ≈ 9.995 and
    // x = 10 + (400 − 0.05)/101 ≈ 49.60, so columns 10..50 are drawn: 41 pixels. Row of column x:
    // x = 10..14 -> 100.05..100.45 -> 100; x = 15..24 -> 100.55..101.45 -> 101; x = 25 -> 101.55
    // -> 102 and beyond. Rows 99..101 are in the band: columns 10..24, 15 pixels. Ratio 15/41.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(10, 100.05, 110, 110.05)) ==
          Approx(15.0 / 41.0).epsilon(1e-12));
    // The same with the line falling: rows 100, 99 inside, 98 from x = 25: again 15/41.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(10, 99.95, 110, 89.95)) ==
          Approx(15.0 / 41.0).epsilon(1e-12));
}

TEST_CASE("overlap: the band ends at the truth's end points, not the infinite line",
          "[line_motion]") {
    // Truth y = 100, x in [10, 50]; tracked: the vertical x = 50.6. Both truth ends project to
    // (50.6, 100): one pixel, (51, 100), 1 px from the end (50, 100): inside, ratio 1.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(50.6, 0, 50.6, 200)) == 1.0);
    // x = 51.6: pixel (52, 100) is 2 px past the end, though on the truth's infinite line: 0.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(51.6, 0, 51.6, 200)) == 0.0);
    // A wider band takes it in: band 4 px, half-band 2 px.
    CHECK(sc::overlap_ratio({10, 100, 50, 100}, tracked(51.6, 0, 51.6, 200), 4.0) == 1.0);
    CHECK_THROWS_AS(sc::overlap_ratio({10, 100, 50, 100}, tracked(0, 0, 1, 1), 0.0),
                    std::invalid_argument);
}

TEST_CASE("measured_segment matches an independent construction", "[line_motion]") {
    const sc::GtSegment cases[] = {{20.3, 40.7, 140.2, 95.1},
                                   {140.2, 95.1, 20.3, 40.7},
                                   {-30, 5, 40, -12.5},
                                   {100, 0, 100, 50}};
    for (const sc::GtSegment& g : cases) {
        const Segment m = sc::measured_segment(g), r = segment(g.x1, g.y1, g.x2, g.y2, 0);
        INFO("segment (" << g.x1 << ", " << g.y1 << ") - (" << g.x2 << ", " << g.y2 << ")");
        CHECK(m.x1 == r.x1);
        CHECK(m.y2 == r.y2);
        CHECK(m.rho.raw >= 0);
        CHECK(std::abs(m.rho.raw - r.rho.raw) <= 1);
        CHECK(std::abs(static_cast<int32_t>(m.theta - r.theta)) <= 1);  // binary angle units
        CHECK(std::abs(m.cx.raw - r.cx.raw) <= 1);
        CHECK(std::abs(m.cy.raw - r.cy.raw) <= 1);
        CHECK(m.points == 0);
        CHECK(m.bright_side == 0);
    }
    CHECK_THROWS_AS(sc::measured_segment({1, 2, 1, 2}), std::invalid_argument);
}

TEST_CASE("Experiment 1 data: random segments translate k·v px per frame", "[line_motion]") {
    const std::vector<sc::GtSegment> segs = sc::random_segments(7);
    REQUIRE(segs.size() == 20);
    CHECK(sc::random_segments(7)[5].x1 == segs[5].x1);  // deterministic
    CHECK(sc::random_segments(8)[5].x1 != segs[5].x1);
    for (const sc::GtSegment& s : segs) {
        const double cx = (s.x1 + s.x2) / 2, cy = (s.y1 + s.y2) / 2;
        CHECK(cx >= 0);
        CHECK(cx <= 319);
        CHECK(cy >= 0);
        CHECK(cy <= 239);
        CHECK(length(s) >= 40 - 1e-9);
        CHECK(length(s) <= 160 + 1e-9);
    }
    // Direction 30°, 3 px/frame: frame k is 3k px from frame 0 along (cos 30°, sin 30°).
    const sc::GtTrack t = sc::translation_track(segs[0], 30, 3);
    REQUIRE(t.size() == 20);
    for (int k = 0; k < 20; ++k) {
        CHECK(midpoint_dist(t[k], t[0]) == Approx(3.0 * k).margin(1e-9));
        CHECK(t[k].x1 - t[0].x1 == Approx(3.0 * k * std::sqrt(3.0) / 2).margin(1e-9));
        CHECK(t[k].y1 - t[0].y1 == Approx(1.5 * k).margin(1e-9));
        CHECK(length(t[k]) == Approx(length(t[0])).epsilon(1e-12));
    }
}

TEST_CASE("Experiment 2 data: the line keeps its Hough r while it turns", "[line_motion]") {
    const std::vector<double> starts = sc::random_start_angles(3);
    REQUIRE(starts.size() == 20);
    for (double th0 : starts) {
        CHECK(th0 >= 0);
        CHECK(th0 < 360);
    }
    const sc::Point2 centres[] = {{0, 0}, {159.5, 119.5}};
    for (sc::Point2 c : centres) {
        const sc::GtTrack t = sc::rotation_track(c, 50, starts[0], 8);
        REQUIRE(t.size() == 20);
        for (int k = 0; k < 20; ++k) {
            CHECK(line_dist(t[k], c) == Approx(50).margin(1e-9));
            CHECK(length(t[k]) == Approx(100).margin(1e-9));
            // The midpoint is the tangent point c + r·n_k, n_k at θ0 + 8k degrees.
            const double mx = (t[k].x1 + t[k].x2) / 2 - c.x, my = (t[k].y1 + t[k].y2) / 2 - c.y;
            const double deg = std::atan2(my, mx) * 180 / qt::ref::kPi;
            const double turn = std::remainder(deg - starts[0] - 8.0 * k, 360.0);
            CHECK(turn == Approx(0).margin(1e-9));
        }
    }
    // About the origin the measured rho is r itself.
    const sc::GtTrack t = sc::rotation_track({0, 0}, 10, 33, 16);
    for (const sc::GtSegment& g : t)
        CHECK(std::abs(sc::measured_segment(g).rho.raw - 10 * 65536) <= 1);
}

TEST_CASE("a line that does not move is tracked exactly by every model", "[line_motion]") {
    // No motion: every prediction is the measured line itself, which scores 1 (see above).
    const sc::GtTrack still(20, sc::GtSegment{30.2, 60.7, 150.4, 20.1});
    for (int n = 1; n <= 3; ++n)
        CHECK(sc::track_mean_overlap(still, tracker(LineModel::closest_points, n)) == 1.0);
    CHECK(sc::track_mean_overlap(still, tracker(LineModel::turn)) == 1.0);
    CHECK_THROWS_AS(sc::track_mean_overlap(sc::GtTrack(1, still[0]), tracker(LineModel::turn)),
                    std::invalid_argument);
}

TEST_CASE("acceptance: turn model keeps >= 80 % overlap at 8 deg/frame about the origin",
          "[line_motion][acceptance]") {
    const sc::RotationTable t = sc::rotation_experiment(tracker(LineModel::turn), {0, 0});
    REQUIRE(t.omegas_deg.size() == 5);
    REQUIRE(t.omegas_deg[3] == 8);
    for (std::size_t r = 0; r < t.radii.size(); ++r) {
        INFO("r = " << t.radii[r] << " px: overlap " << 100 * t.overlap[r][3] << " %");
        CHECK(t.overlap[r][3] >= 0.80);
    }
}

TEST_CASE("acceptance: turn model matches 3KF in translation", "[line_motion][acceptance]") {
    const sc::TranslationTable turn = sc::translation_experiment(tracker(LineModel::turn));
    const sc::TranslationTable kf3 =
        sc::translation_experiment(tracker(LineModel::closest_points, 3));
    REQUIRE(turn.speeds.size() == 3);
    for (std::size_t s = 0; s < turn.speeds.size(); ++s) {
        const double a = sc::mean_of(turn.overlap[s]), b = sc::mean_of(kf3.overlap[s]);
        INFO("speed " << turn.speeds[s] << " px/frame: turn " << 100 * a << " %, 3KF " << 100 * b
                      << " %");
        CHECK(a >= b - 0.01);
    }
}

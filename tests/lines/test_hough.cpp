// PPHT: its accumulator against a double-precision Hough on the same votes, determinism,
// degenerate frames and every capacity and budget limit.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "base/prng.h"
#include "lines/line_detector.h"
#include "lines/visit_order.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

LineDetectorQvga g_det;

// QVGA with small segment and line lists, to fill them.
struct ThreeSegmentsTwoLines : Qvga {
    static constexpr uint16_t segments = 3, lines = 2;
};
struct FourSegments : Qvga {
    static constexpr uint16_t segments = 4, lines = 4;
};

Status detect(const io::GreyImage& img, const LineParams& p) {
    REQUIRE(g_det.begin_frame(static_cast<uint16_t>(img.width), static_cast<uint16_t>(img.height),
                              p) == Status::ok);
    for (int y = 0; y < img.height; ++y)
        REQUIRE(g_det.push_row(img.row(y), static_cast<uint16_t>(img.width)) == Status::ok);
    return g_det.finish();
}

// The detector's segments (or lines) equal `want`, end for end and angle for angle.
void require_same(const Segment* got, uint16_t count, const std::vector<Segment>& want) {
    REQUIRE(count == want.size());
    for (uint16_t i = 0; i < count; ++i) {
        REQUIRE(got[i].x1 == want[i].x1);
        REQUIRE(got[i].y1 == want[i].y1);
        REQUIRE(got[i].x2 == want[i].x2);
        REQUIRE(got[i].y2 == want[i].y2);
        REQUIRE(got[i].theta == want[i].theta);
    }
}

io::GreyImage polygon_frame(uint64_t seed) {
    scene::SceneOptions o;
    o.noise_sigma = 5;
    o.blur_sigma = 0.7;
    o.seed = seed;
    return scene::random_polygon_scene(o, 2, 40, 60).render();
}

// Whether the detector's lines hold one along the segment side = {x1, y1, x2, y2} (px): both
// ends within 2 px of its line and at least 0.6 of its length.
bool side_found(const double (&side)[4]) {
    const double dx = side[2] - side[0], dy = side[3] - side[1];
    const double len = std::hypot(dx, dy);
    for (uint16_t i = 0; i < g_det.line_count(); ++i) {
        const Segment& l = g_det.lines()[i];
        const double ends[2][2] = {{l.x1.raw / 65536.0, l.y1.raw / 65536.0},
                                   {l.x2.raw / 65536.0, l.y2.raw / 65536.0}};
        bool near = true;
        for (const auto& e : ends)
            near = near && std::fabs((e[0] - side[0]) * dy - (e[1] - side[1]) * dx) / len < 2.0;
        const double l_len = std::hypot(ends[1][0] - ends[0][0], ends[1][1] - ends[0][1]);
        if (near && l_len >= 0.6 * len) return true;
    }
    return false;
}

// A bright 200 x 140 box (columns 60..259, rows 50..189) on grainy noise, and its sides on the
// pixel boundaries (an edge between x0 - 1 and x0 lies at x0 - 0.5).
io::GreyImage box_on_grain(double (&sides)[4][4]) {
    io::GreyImage img(320, 240);
    Pcg32 rng(11);
    const int x0 = 60, y0 = 50, x1 = 260, y1 = 190;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
            img.at(x, y) = static_cast<uint8_t>((inside ? 190 : 40) + rng.next() % 48u);
        }
    const double s[4][4] = {{x0 - 0.5, y0 - 0.5, x1 - 0.5, y0 - 0.5},
                            {x1 - 0.5, y0 - 0.5, x1 - 0.5, y1 - 0.5},
                            {x0 - 0.5, y1 - 0.5, x1 - 0.5, y1 - 0.5},
                            {x0 - 0.5, y0 - 0.5, x0 - 0.5, y1 - 0.5}};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) sides[i][k] = s[i][k];
    return img;
}

}  // namespace

TEST_CASE("PPHT accumulator equals a double-precision Hough of the same votes within one bin",
          "[hough]") {
    // A threshold no bin reaches: PPHT only votes, so the accumulator ends up holding every
    // edge point's votes. The reference votes the same points in double precision.
    const io::GreyImage img = polygon_frame(41);
    LineParams p;
    p.hough.threshold = 255;
    REQUIRE(detect(img, p) == Status::ok);
    REQUIRE(g_det.segment_count() == 0);
    const EdgeList& edges = g_det.edges();
    const int n_theta = p.hough.theta_bins, step = p.hough.rho_step;
    const int half = static_cast<int>((hough_bins_for(320, 240, n_theta, step) / n_theta - 1) / 2);
    const int n_rho = 2 * half + 1;
    std::vector<int> ref(static_cast<size_t>(n_theta * n_rho), 0),
        ambiguous(static_cast<size_t>(n_theta), 0);
    const double kPi = 3.14159265358979323846;
    const int window = (p.hough.vote_window_deg * n_theta + 179) / 180;
    for (uint16_t i = 0; i < edges.size(); ++i) {
        const double x = ep::x(edges[i]) - 160.0, y = ep::y(edges[i]) - 120.0;
        // The line normal is the gradient direction: bin d points at d·22.5°, mod 180°.
        const int centre =
            static_cast<int>(std::lround((ep::dir(edges[i]) % 8) * 22.5 / (180.0 / n_theta)));
        for (int j = centre - window; j <= centre + window; ++j) {
            const int t = (j + n_theta) % n_theta;
            const double theta = t * kPi / n_theta;
            const double u = (x * std::cos(theta) + y * std::sin(theta)) / step + 0.5;
            const int r = static_cast<int>(std::floor(u)) + half;
            REQUIRE(r >= 0);
            REQUIRE(r < n_rho);
            ++ref[static_cast<size_t>(t * n_rho + r)];
            const double frac = u - std::floor(u);
            if (frac < 0.01 || frac > 0.99) ++ambiguous[static_cast<size_t>(t)];
        }
    }
    // The detector keeps its accumulator to itself: run hough_segments again on the same
    // points (a second view of the detector's list, states reset) into storage we can read.
    static HoughStorage<hough_bins_for(320, 240, 90, 2), 90> storage;
    EdgeList copy = edges;
    for (uint16_t i = 0; i < copy.size(); ++i) copy[i] = ep::with_state(copy[i], ep::kFresh);
    Segment out[4];
    uint16_t count = 0;
    HoughStats stats;
    // A frame with other θ bins first: the sin/cos tables the storage keeps between frames must
    // be made again for this one.
    HoughParams other = p.hough;
    other.theta_bins = 60;
    REQUIRE(hough_segments(copy, 320, 240, other, storage.view(), out, 4, &count, &stats) ==
            Status::ok);
    for (uint16_t i = 0; i < copy.size(); ++i) copy[i] = ep::with_state(copy[i], ep::kFresh);
    REQUIRE(hough_segments(copy, 320, 240, p.hough, storage.view(), out, 4, &count, &stats) ==
            Status::ok);
    REQUIRE(count == 0);
    long total_fixed = 0, total_ref = 0;
    for (int t = 0; t < n_theta; ++t) {
        long cum_fixed = 0, cum_ref = 0;
        for (int r = 0; r < n_rho; ++r) {
            cum_fixed += storage.bins[t * n_rho + r];
            cum_ref += ref[static_cast<size_t>(t * n_rho + r)];
            // A vote may only move to the neighbouring bin, and only when its exact rho lies
            // within 1 % of a bin of a rounding boundary (the Q14 tables' error is far below).
            INFO("theta bin " << t << " rho bin " << r);
            REQUIRE(std::labs(cum_fixed - cum_ref) <= ambiguous[static_cast<size_t>(t)]);
        }
        total_fixed += cum_fixed;
        total_ref += cum_ref;
    }
    REQUIRE(total_fixed == total_ref);
    REQUIRE(total_fixed == static_cast<long>(stats.votes));
}

TEST_CASE("PPHT is deterministic for a seed and depends on it", "[hough]") {
    const io::GreyImage img = polygon_frame(42);
    LineParams p;
    REQUIRE(detect(img, p) == Status::ok);
    std::vector<Segment> first(g_det.segments(), g_det.segments() + g_det.segment_count());
    REQUIRE(detect(img, p) == Status::ok);
    require_same(g_det.segments(), g_det.segment_count(), first);
    p.hough.seed = 99;
    REQUIRE(detect(img, p) == Status::ok);
    bool differs = g_det.segment_count() != first.size();
    for (size_t i = 0; !differs && i < first.size(); ++i)
        differs = g_det.segments()[i].x1 != first[i].x1;
    REQUIRE(differs);  // another order finds the segments in another order at least
}

TEST_CASE("degenerate frames: blank, all-edge noise, one pixel, lines along every border",
          "[hough]") {
    LineParams p;
    io::GreyImage blank(320, 240, 100);
    REQUIRE(detect(blank, p) == Status::ok);
    REQUIRE(g_det.stats().edges == 0);
    REQUIRE(g_det.line_count() == 0);

    io::GreyImage noise(320, 240);
    Pcg32 rng(5);
    for (uint8_t& v : noise.pixels) v = static_cast<uint8_t>(rng.next());
    REQUIRE(detect(noise, p) == Status::capacity_exceeded);
    const LineStats& s = g_det.stats();
    // Full: the list dropped its weakest quarter at least once and kept the strongest edges
    // (every edge at or above its floor, which rose above the threshold); the rest is
    // reported, not lost silently.
    REQUIRE(s.edges >= 3072);
    REQUIRE(s.edges <= 4096);
    REQUIRE(g_det.edges().floor() > p.edge_threshold);
    REQUIRE(s.edges_dropped > 0);
    REQUIRE(s.hough.walk_steps <= p.hough.max_walk_steps);

    io::GreyImage one(1, 1, 7);
    REQUIRE(detect(one, p) == Status::ok);
    REQUIRE(g_det.line_count() == 0);

    io::GreyImage border(320, 240, 0);
    for (int x = 0; x < 320; ++x) border.at(x, 0) = border.at(x, 239) = 255;
    for (int y = 0; y < 240; ++y) border.at(0, y) = border.at(319, y) = 255;
    REQUIRE(detect(border, p) == Status::ok);
    REQUIRE(g_det.line_count() >= 4);
    for (uint16_t i = 0; i < g_det.line_count(); ++i) {
        const Segment& l = g_det.lines()[i];
        for (q16_16 c : {l.x1, l.x2}) REQUIRE((c.raw >= -65536 && c.raw <= 320 * 65536));
        for (q16_16 c : {l.y1, l.y2}) REQUIRE((c.raw >= -65536 && c.raw <= 240 * 65536));
    }
}

TEST_CASE("limits are reported: segment capacity, walk budget, bad parameters", "[hough]") {
    const io::GreyImage img = polygon_frame(43);
    LineDetector<ThreeSegmentsTwoLines> small;
    LineParams p;
    REQUIRE(small.begin_frame(320, 240, p) == Status::ok);
    for (int y = 0; y < 240; ++y) REQUIRE(small.push_row(img.row(y), 320) == Status::ok);
    REQUIRE(small.finish() == Status::capacity_exceeded);
    REQUIRE(small.segment_count() == 3);
    REQUIRE(small.stats().hough.segments_dropped > 0);

    p.hough.max_walk_steps = 50;
    REQUIRE(detect(img, p) == Status::capacity_exceeded);
    REQUIRE(g_det.stats().hough.budget_exhausted);
    REQUIRE(g_det.stats().hough.walk_steps == 50);

    LineParams bad;
    bad.hough.rho_step = 3;  // 1, 2 or 4 only
    REQUIRE(g_det.begin_frame(320, 240, bad) == Status::ok);
    io::GreyImage flat(320, 240, 9);
    for (int y = 0; y < 240; ++y) REQUIRE(g_det.push_row(flat.row(y), 320) == Status::ok);
    REQUIRE(g_det.finish() == Status::bad_size);
    bad = LineParams{};
    bad.hough.rho_step = 1;  // needs twice the bins this detector has
    REQUIRE(g_det.begin_frame(320, 240, bad) == Status::ok);
    for (int y = 0; y < 240; ++y) REQUIRE(g_det.push_row(flat.row(y), 320) == Status::ok);
    REQUIRE(g_det.finish() == Status::bad_size);
    REQUIRE(g_det.begin_frame(321, 240, LineParams{}) == Status::bad_size);
    REQUIRE(g_det.begin_frame(320, 241, LineParams{}) == Status::bad_size);

    // A refused frame leaves nothing to finish, not the previous frame's edges again.
    REQUIRE(detect(img, LineParams{}) == Status::ok);
    REQUIRE(g_det.begin_frame(320, 241, LineParams{}) == Status::bad_size);
    REQUIRE(g_det.finish() == Status::not_in_frame);
    REQUIRE(g_det.begin_frame(321, 240, LineParams{}) == Status::bad_size);
    REQUIRE(g_det.finish() == Status::not_in_frame);
}

TEST_CASE("the voting budget bounds the points that vote and keeps a clear board's sides",
          "[hough]") {
    // A bright 200 x 140 box on grainy noise: the noise gives thousands of edge points, more
    // than half the list, so the default budget (half the capacity, 2048) binds.
    double sides[4][4];
    const io::GreyImage img = box_on_grain(sides);
    LineParams p;
    REQUIRE(detect(img, p) == Status::capacity_exceeded);
    const HoughStats by_default = g_det.stats().hough;
    REQUIRE(by_default.voters_exhausted);
    REQUIRE(by_default.points_visited == 2048);
    REQUIRE_FALSE(by_default.budget_exhausted);
    for (const auto& side : sides) REQUIRE(side_found(side));
    std::vector<Segment> default_lines(g_det.lines(), g_det.lines() + g_det.line_count());

    // 0 means half the capacity: the explicit value gives the same lines.
    p.hough.max_voters = 2048;
    REQUIRE(detect(img, p) == Status::capacity_exceeded);
    require_same(g_det.lines(), g_det.line_count(), default_lines);

    // A quarter of the capacity: exactly that many vote, and the box's long sides still pass
    // the vote threshold before it binds (at 400 one of them does not).
    p.hough.max_voters = 1024;
    REQUIRE(detect(img, p) == Status::capacity_exceeded);
    REQUIRE(g_det.stats().hough.voters_exhausted);
    REQUIRE(g_det.stats().hough.points_visited == 1024);
    REQUIRE(g_det.stats().hough.votes < by_default.votes / 2 + by_default.votes / 8);
    for (const auto& side : sides) REQUIRE(side_found(side));

    // No budget to speak of (more than the list holds): every fresh point votes.
    p.hough.max_voters = 65535;
    detect(img, p);
    REQUIRE_FALSE(g_det.stats().hough.voters_exhausted);
    REQUIRE(g_det.stats().hough.points_visited > 2048);
}

TEST_CASE(
    "a bin at the threshold is followed when it stands out on one side: grain waits, a "
    "bar's two edges and stripes do not",
    "[hough]") {
    // The box on grain: most bins the grain raises to the threshold have grain on both flanks
    // and are not followed; the box's sides still are, with fewer walks than the reference PPHT.
    double sides[4][4];
    const io::GreyImage grain = box_on_grain(sides);
    LineParams reference;
    reference.hough.min_peak_percent = 0;
    detect(grain, reference);
    const HoughStats all = g_det.stats().hough;
    REQUIRE(all.flat_bins == 0);
    detect(grain, LineParams{});
    const HoughStats peaks = g_det.stats().hough;
    REQUIRE(peaks.flat_bins > 0);
    REQUIRE(peaks.lines_followed < all.lines_followed);
    REQUIRE(peaks.walk_steps < all.walk_steps);
    for (const auto& side : sides) REQUIRE(side_found(side));

    // Dark bars 5 px wide on a flat grey: a bar's two edges are 5 px apart, so each edge's bin
    // has the other's 2 or 3 bins beside it (rho 2 px) and only the far flank low. Five stripes
    // 5 px apart (dark 5, light 5): an inner edge has edges on both flanks until its
    // neighbours are consumed. Every edge is found, and with the reference PPHT too.
    for (const int bars : {1, 5}) {
        io::GreyImage img(320, 240, 150);
        const int left = 100, top = 40, bottom = 200;  // rows top..bottom - 1
        for (int b = 0; b < bars; ++b)
            for (int y = top; y < bottom; ++y)
                for (int x = left + 10 * b; x < left + 10 * b + 5; ++x) img.at(x, y) = 60;
        for (const LineParams& p : {LineParams{}, reference}) {
            REQUIRE(detect(img, p) == Status::ok);
            for (int e = 0; e < 2 * bars; ++e) {
                const double x = left + 5 * e - 0.5;
                const double edge[4] = {x, top + 0.0, x, bottom - 1.0};
                CAPTURE(bars, e, p.hough.min_peak_percent);
                REQUIRE(side_found(edge));
            }
        }
    }
}

TEST_CASE("the QVGA lines stage fits 48 KiB of RAM", "[hough]") {
    STATIC_REQUIRE(LineDetectorQvga::ram_bytes() <= 48 * 1024);
    REQUIRE(LineDetectorQvga::ram_bytes() == sizeof(LineDetectorQvga));
}

TEST_CASE(
    "a segment's end: a run after a gap of g pixels counts once it has g points or another run "
    "follows",
    "[hough]") {
    // Hand-built edge lists: the row y = 50 from x = 20 to 99 (a horizontal edge, gradient
    // direction bin 4), then points past a gap. Expected ends worked by hand from the rule.
    struct Case {
        std::vector<int> after;  // x of the points past x = 99
        int end_x;               // the segment's right end
    };
    const Case cases[] = {
        {{}, 99},
        {{103}, 99},             // gap 3, one point: noise
        {{103, 104}, 99},        // gap 3, a run of 2 < 3
        {{103, 104, 105}, 105},  // gap 3, a run of 3
        {{101}, 101},            // gap 1: part of the line at once
        {{102, 105, 108}, 105},  // runs of 1 after gaps of 2: each counts once the next begins
        {{102, 103, 107}, 103},  // a run of 2 after a gap of 2 counts; the lone 107 does not
    };
    static EdgeListStorage<256, 100> storage;
    static HoughStorage<hough_bins_for(160, 100, 90, 2), 90> accumulator;
    // Every visiting order: whichever point's vote starts the walk (a noise point past the gap
    // among them), the rule gives the same end.
    for (uint64_t seed = 1; seed <= 60; ++seed)
        for (const Case& c : cases) {
            EdgeList list = storage.view();
            REQUIRE(list.begin_frame(100) == Status::ok);
            list.begin_row(50);
            for (int x = 20; x <= 99; ++x) REQUIRE(list.push(static_cast<uint16_t>(x), 4, 0, 100));
            for (int x : c.after) REQUIRE(list.push(static_cast<uint16_t>(x), 4, 0, 100));
            list.end_frame();
            Segment out[4];
            uint16_t count = 0;
            HoughStats stats;
            HoughParams params;
            params.seed = seed;
            REQUIRE(hough_segments(list, 160, 100, params, accumulator.view(), out, 4, &count,
                                   &stats) == Status::ok);
            INFO("points past the gap: " << c.after.size() << ", expected end " << c.end_x
                                         << ", seed " << seed);
            REQUIRE(count == 1);
            const double right = std::max(out[0].x1.raw, out[0].x2.raw) / 65536.0;
            const double left = std::min(out[0].x1.raw, out[0].x2.raw) / 65536.0;
            REQUIRE(left == Approx(20).margin(0.01));
            REQUIRE(right == Approx(c.end_x).margin(0.01));
        }
}

TEST_CASE("a full segment list keeps the longest segments, whatever the visiting order",
          "[hough]") {
    // Eight bright bars 10 px tall and 30, 40, ..., 100 px wide: their top and bottom sides
    // are 16 segments (the 10-px ends are below min_line_length). With room for 4, the 4 kept
    // are the sides of the two widest bars, for any PPHT seed.
    scene::SceneOptions o;
    o.background = 40;
    o.blur_sigma = 0.7;
    o.noise_sigma = 2;
    scene::LineScene ls(o);
    for (int k = 0; k < 8; ++k) {
        const double w = 30 + 10 * k, x = 10 + (k % 2) * 150, y = 12 + 28 * k;
        ls.add_polygon({{x, y}, {x + w, y}, {x + w, y + 10}, {x, y + 10}}, 200);
    }
    const io::GreyImage img = ls.render();
    static LineDetector<FourSegments> small;
    for (uint64_t seed = 1; seed <= 6; ++seed) {
        LineParams p;
        p.hough.seed = seed;
        REQUIRE(small.begin_frame(320, 240, p) == Status::ok);
        for (int y = 0; y < 240; ++y) REQUIRE(small.push_row(img.row(y), 320) == Status::ok);
        REQUIRE(small.finish() == Status::capacity_exceeded);
        REQUIRE(small.segment_count() == 4);
        CHECK(small.stats().hough.segments_dropped >= 12);
        for (uint16_t i = 0; i < 4; ++i) {
            const Segment& s = small.segments()[i];
            const double len =
                std::hypot((s.x2.raw - s.x1.raw) / 65536.0, (s.y2.raw - s.y1.raw) / 65536.0);
            INFO("seed " << seed << " segment " << i << " length " << len);
            CHECK(len > 85);  // of the 90- and 100-px bars (ends stop a pixel or two short)
        }
    }
}

TEST_CASE("PPHT's visiting order is a permutation, spread over the list, set by the seed",
          "[hough]") {
    for (uint32_t n : {0u, 1u, 2u, 3u, 5u, 64u, 1000u, 4097u, 65535u}) {
        std::vector<bool> seen(n, false);
        VisitOrder order(n, 7);
        double jumps = 0;
        uint32_t last = 0;
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t v = order.next();
            REQUIRE(v < n);
            REQUIRE_FALSE(seen[v]);
            seen[v] = true;
            if (k > 0) jumps += std::abs(static_cast<double>(v) - last);
            last = v;
        }
        // Consecutive indices of a random permutation lie n/3 apart on average; a scan in list
        // (raster) order would give 1.
        if (n >= 1000) {
            const double mean = jumps / (n - 1);
            INFO("n " << n << ": mean jump " << mean);
            REQUIRE(mean > n / 4.0);
            REQUIRE(mean < n / 2.5);
        }
    }
    VisitOrder a(1000, 1), b(1000, 2);
    int same = 0;
    for (int k = 0; k < 1000; ++k) same += a.next() == b.next();
    REQUIRE(same < 20);
}

TEST_CASE("a walk's list too long for the spare words falls back to searching the corridor",
          "[hough]") {
    // A 200-px horizontal and a 150-px vertical edge, each one segment. In an edge list of 360
    // points the list of points a walk found (in its spare words, capacity / 2 = 180 of them)
    // overflows on the horizontal edge, whose points are then consumed by searching its
    // corridor again; in a list of 2048 they all come from the list. Both give the same
    // segments and consume every point.
    auto run = [](auto& storage, std::vector<Segment>& segments, uint32_t& unconsumed) {
        EdgeList list = storage.view();
        REQUIRE(list.begin_frame(240) == Status::ok);
        for (uint16_t y = 0; y < 240; ++y) {
            list.begin_row(y);
            if (y >= 40 && y < 190) REQUIRE(list.push(250, 0, 0, 100));
            if (y == 20)
                for (uint16_t x = 10; x < 210; ++x) REQUIRE(list.push(x, 4, 0, 100));
        }
        list.end_frame();
        static HoughStorage<hough_bins_for(320, 240, 90, 2), 90> accumulator;
        Segment out[8];
        uint16_t count = 0;
        HoughStats stats;
        REQUIRE(hough_segments(list, 320, 240, HoughParams{}, accumulator.view(), out, 8, &count,
                               &stats) == Status::ok);
        segments.assign(out, out + count);
        unconsumed = 0;
        for (uint16_t i = 0; i < list.size(); ++i)
            unconsumed += ep::state(list[i]) != ep::kConsumed;
    };
    static EdgeListStorage<360, 240> small;
    static EdgeListStorage<2048, 240> large;
    std::vector<Segment> from_corridor, from_list;
    uint32_t left_corridor = 0, left_list = 0;
    run(small, from_corridor, left_corridor);
    run(large, from_list, left_list);
    REQUIRE(from_list.size() == 2);
    REQUIRE(from_corridor.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
        REQUIRE(from_list[k].x1.raw == from_corridor[k].x1.raw);
        REQUIRE(from_list[k].y1.raw == from_corridor[k].y1.raw);
        REQUIRE(from_list[k].x2.raw == from_corridor[k].x2.raw);
        REQUIRE(from_list[k].y2.raw == from_corridor[k].y2.raw);
        REQUIRE(from_list[k].theta == from_corridor[k].theta);
    }
    REQUIRE(left_list == 0);
    REQUIRE(left_corridor == 0);
}

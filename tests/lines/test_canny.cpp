// The lines stage's Canny front end (the Quadrangle Detection paper §2.3; LineParams::front_end =
// canny): the streaming binomial smoothing (core/lines/smooth_rows.h) against a direct 2-D
// convolution written here in double with replicated borders, hysteresis (EdgeList::hysteresis)
// against a breadth-first flood fill over a magnitude bitmap written here, and the whole stage in
// Canny mode on noisy polygon scenes.
#include <catch2/catch.hpp>

#include <cmath>
#include <deque>
#include <vector>

#include "base/prng.h"
#include "lines/edge_list.h"
#include "lines/line_detector.h"
#include "lines/smooth_rows.h"
#include "scene/line_match.h"
#include "scene/line_scene.h"

using namespace qt;

namespace {

// [1 2 1] ⊗ [1 2 1] / 16 at (x, y), borders replicated, rounded half up, in double.
int smooth_reference(const std::vector<uint8_t>& img, int w, int h, int x, int y) {
    const double k[3] = {1, 2, 1};
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int xx = std::min(std::max(x + dx, 0), w - 1);
            const int yy = std::min(std::max(y + dy, 0), h - 1);
            sum += k[dx + 1] * k[dy + 1] * img[static_cast<size_t>(yy * w + xx)];
        }
    return static_cast<int>(std::floor(sum / 16 + 0.5));
}

}  // namespace

TEST_CASE("SmoothRows equals the direct 2-D binomial convolution, any size", "[canny]") {
    static SmoothRows<64> s;
    Pcg32 rng(11);
    for (const auto& size : std::vector<std::pair<int, int>>{
             {1, 1}, {1, 7}, {9, 1}, {2, 2}, {3, 5}, {17, 13}, {64, 40}}) {
        const int w = size.first, h = size.second;
        std::vector<uint8_t> img(static_cast<size_t>(w * h));
        for (uint8_t& p : img) p = static_cast<uint8_t>(rng.below(256));
        REQUIRE(s.begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h)) == Status::ok);
        std::vector<std::vector<int>> out;
        for (int y = 0; y < h; ++y)
            REQUIRE(s.push_row(&img[static_cast<size_t>(y * w)], static_cast<uint16_t>(w),
                               [&](const uint8_t* row, uint16_t n) {
                                   out.emplace_back(row, row + n);
                               }) == Status::ok);
        REQUIRE(static_cast<int>(out.size()) == h);
        CHECK_FALSE(s.in_frame());
        int wrong = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                wrong += out[static_cast<size_t>(y)][static_cast<size_t>(x)] !=
                         smooth_reference(img, w, h, x, y);
        INFO(w << " x " << h);
        CHECK(wrong == 0);
    }
    REQUIRE(s.begin_frame(8, 4) == Status::ok);
    uint8_t row[9] = {};
    CHECK(s.push_row(row, 9, [](const uint8_t*, uint16_t) {}) == Status::bad_row_length);
    CHECK(s.push_row(row, 8, [](const uint8_t*, uint16_t) {}) == Status::not_in_frame);
    CHECK(s.begin_frame(65, 4) == Status::bad_size);
}

TEST_CASE("Hysteresis keeps exactly the points joined to a strong one, as a flood fill does",
          "[canny]") {
    constexpr int W = 40, H = 30;
    static EdgeListStorage<1024, H> storage;
    static uint8_t scratch[2048];
    Pcg32 rng(5);
    for (int trial = 0; trial < 20; ++trial) {
        // A random magnitude map: about 35 % of the pixels are edges of magnitude 20..200.
        std::vector<int> mag(W * H, 0);
        for (int& m : mag)
            if (rng.below(100) < 35) m = 20 + static_cast<int>(rng.below(181));
        EdgeList list = storage.view();
        REQUIRE(list.begin_frame(H) == Status::ok);
        for (int y = 0; y < H; ++y) {
            list.begin_row(static_cast<uint16_t>(y));
            for (int x = 0; x < W; ++x)
                if (mag[y * W + x])
                    REQUIRE(list.push(static_cast<uint16_t>(x), 0, 0,
                                      static_cast<uint32_t>(mag[y * W + x])));
        }
        list.end_frame();
        const uint16_t high = 150;
        // The reference: breadth-first from every pixel >= high through 8-neighbours.
        std::vector<char> keep(W * H, 0);
        std::deque<int> q;
        for (int i = 0; i < W * H; ++i)
            if (mag[i] >= high) {
                keep[i] = 1;
                q.push_back(i);
            }
        while (!q.empty()) {
            const int i = q.front();
            q.pop_front();
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = i % W + dx, y = i / W + dy;
                    if (x < 0 || y < 0 || x >= W || y >= H) continue;
                    const int j = y * W + x;
                    if (mag[j] && !keep[j]) {
                        keep[j] = 1;
                        q.push_back(j);
                    }
                }
        }
        int want = 0, edges = 0;
        for (int i = 0; i < W * H; ++i) {
            want += keep[i];
            edges += mag[i] != 0;
        }
        const uint32_t removed = list.hysteresis(high, scratch, sizeof scratch);
        INFO("trial " << trial);
        CHECK(removed == static_cast<uint32_t>(edges - want));
        REQUIRE(list.size() == want);
        int wrong = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const int32_t i = list.find(x, y);
                wrong += (i >= 0) != (keep[y * W + x] != 0);
                if (i >= 0) wrong += ep::state(list[static_cast<uint16_t>(i)]) != ep::kFresh;
            }
        CHECK(wrong == 0);
        CHECK(list.dropped() == 0);  // a rule, not a capacity
    }
    // Too little scratch: nothing done.
    EdgeList list = storage.view();
    REQUIRE(list.begin_frame(H) == Status::ok);
    list.begin_row(0);
    for (uint16_t x = 0; x < 4; ++x) list.push(x, 0, 0, 30);
    list.end_frame();
    CHECK(list.hysteresis(100, scratch, 7) == 0);
    CHECK(list.size() == 4);
}

TEST_CASE("The Canny front end finds the sides of noisy polygons", "[canny]") {
    static LineDetectorQvga det;
    LineParams p;
    p.front_end = EdgeFrontEnd::canny;
    p.edge_threshold = 16;  // low enough that noise makes weak edges for hysteresis to drop
    p.canny_high = 60;
    int scored = 0, found = 0, fp = 0, weak_dropped = 0;
    for (int i = 0; i < 20; ++i) {
        scene::SceneOptions o;
        o.noise_sigma = 5;
        o.blur_sigma = 0.7;
        o.seed = 3000 + static_cast<uint64_t>(i);
        const scene::LineScene s = scene::random_polygon_scene(o, 2, 40, 60);
        const io::GreyImage img = s.render();
        REQUIRE(det.begin_frame(320, 240, p) == Status::ok);
        for (int y = 0; y < 240; ++y) REQUIRE(det.push_row(img.row(y), 320) == Status::ok);
        REQUIRE(det.finish() == Status::ok);
        weak_dropped += static_cast<int>(det.stats().edges_hysteresis);
        std::vector<scene::DetectedLine> d;
        for (uint16_t k = 0; k < det.line_count(); ++k) {
            const Segment& l = det.lines()[k];
            d.push_back({{l.x1.raw / 65536.0, l.y1.raw / 65536.0},
                         {l.x2.raw / 65536.0, l.y2.raw / 65536.0}});
        }
        scene::MatchRule rule;
        rule.min_length = 2.0 * p.hough.min_line_length;
        const scene::MatchResult r = scene::match_lines(s.truth(), d, rule);
        scored += r.scored;
        found += r.found;
        fp += r.false_positives;
    }
    INFO("found " << found << " of " << scored << ", false positives " << fp
                  << ", weak edge points dropped by hysteresis " << weak_dropped);
    CHECK(found >= scored * 95 / 100);
    CHECK(fp == 0);
    CHECK(weak_dropped > 0);  // the noise's weak edges went
}

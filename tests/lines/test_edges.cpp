// Edges: NMS along the quantised direction on hand-worked frames, sub-pixel peaks, the edge
// list's lookups and capacity, and the streaming statuses.
#include <catch2/catch.hpp>
#include <vector>

#include "base/prng.h"
#include "gradient/gradient_stage.h"
#include "lines/edge_stage.h"

using namespace qt;

namespace {

struct Frame {
    int w, h;
    std::vector<uint8_t> px;
    uint8_t& at(int x, int y) { return px[static_cast<size_t>(y * w + x)]; }
};

EdgeListStorage<2048, 64> g_storage;
GradientStage<64> g_gradient;
EdgeStage<64> g_edges;

EdgeList run(Frame& f, uint16_t threshold) {
    EdgeList list = g_storage.view();
    REQUIRE(g_gradient.begin_frame(static_cast<uint16_t>(f.w), static_cast<uint16_t>(f.h)) ==
            Status::ok);
    REQUIRE(g_edges.begin_frame(static_cast<uint16_t>(f.w), static_cast<uint16_t>(f.h), threshold,
                                list) == Status::ok);
    for (int y = 0; y < f.h; ++y)
        REQUIRE(g_gradient.push_row(&f.at(0, y), static_cast<uint16_t>(f.w),
                                    [&](uint16_t, const gradient_word* words, uint16_t n) {
                                        REQUIRE(g_edges.push_row(words, n) == Status::ok);
                                    }) == Status::ok);
    REQUIRE_FALSE(g_edges.in_frame());
    return list;
}

}  // namespace

TEST_CASE("a vertical step gives one edge per row on its bright side, sub-pixel at the step",
          "[edges]") {
    for (bool bright_right : {true, false}) {
        Frame f{20, 10, std::vector<uint8_t>(200)};
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 20; ++x) f.at(x, y) = (x >= 10) == bright_right ? 200 : 50;
        const EdgeList list = run(f, 40);
        // gx = 150 at columns 9 and 10 (central differences straddle the step), 0 elsewhere;
        // NMS keeps the one on the bright side, and the parabola through (150, 150, 0) puts
        // the peak half a pixel back towards the other: at x = 9.5 both ways.
        REQUIRE(list.size() == 10);
        for (uint16_t i = 0; i < list.size(); ++i) {
            INFO("bright_right " << bright_right << " point " << i);
            REQUIRE(ep::y(list[i]) == i);
            REQUIRE(ep::x(list[i]) == (bright_right ? 10u : 9u));
            REQUIRE(ep::dir(list[i]) == (bright_right ? 0u : 8u));
            REQUIRE(ep::x32(list[i]) == 304);  // 9.5 px · 32
            REQUIRE(ep::y32(list[i]) == static_cast<int32_t>(32 * i));
        }
    }
}

TEST_CASE("a horizontal step and a diagonal step", "[edges]") {
    Frame h{12, 12, std::vector<uint8_t>(144)};
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) h.at(x, y) = y >= 6 ? 180 : 20;
    const EdgeList lh = run(h, 40);
    REQUIRE(lh.size() == 12);
    for (uint16_t i = 0; i < lh.size(); ++i) {
        REQUIRE(ep::y(lh[i]) == 6u);
        REQUIRE(ep::dir(lh[i]) == 4u);  // +y: down the image
        REQUIRE(ep::y32(lh[i]) == 5 * 32 + 16);
    }
    // Bright below the diagonal (y > x): gx < 0, gy > 0, so 135°, bin 6. Central differences
    // give the same magnitude to the pixels just either side of the boundary y = x + 0.5, and
    // those are not neighbours along the 135° axis: both stay, a two-pixel chain whose
    // positions lie within half a pixel of the boundary.
    Frame d{16, 16, std::vector<uint8_t>(256)};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) d.at(x, y) = y > x ? 200 : 40;
    const EdgeList ld = run(d, 40);
    REQUIRE(ld.size() >= 12);
    for (uint16_t i = 0; i < ld.size(); ++i) {
        INFO("point " << ep::x(ld[i]) << "," << ep::y(ld[i]));
        REQUIRE(ep::dir(ld[i]) == 6u);
        REQUIRE((ep::y(ld[i]) == ep::x(ld[i]) || ep::y(ld[i]) == ep::x(ld[i]) + 1));
        const int32_t off32 = ep::y32(ld[i]) - ep::x32(ld[i]) - 16;  // (y - x - 0.5) · 32
        REQUIRE(off32 * off32 <= 2 * 16 * 16);                       // distance <= 0.5 px
    }
}

TEST_CASE("edges below the threshold are not reported", "[edges]") {
    Frame f{20, 5, std::vector<uint8_t>(100)};
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 20; ++x) f.at(x, y) = x >= 10 ? 119 : 100;  // gx = 19
    REQUIRE(run(f, 20).size() == 0);
    REQUIRE(run(f, 19).size() == 5);
}

TEST_CASE("edge list lookups agree with a brute-force search, and capacity overflow is counted",
          "[edges]") {
    EdgeListStorage<300, 40> storage;
    EdgeList list = storage.view();
    REQUIRE(list.begin_frame(41) == Status::bad_size);
    REQUIRE(list.begin_frame(40) == Status::ok);
    Pcg32 rng(12);
    std::vector<std::vector<bool>> truth(40, std::vector<bool>(50, false));
    for (uint16_t y = 0; y < 40; y += 1 + static_cast<uint16_t>(rng.below(3))) {
        list.begin_row(y);
        for (uint16_t x = 0; x < 50; ++x)
            if (rng.below(4) == 0 && list.push(x, 0, 0, 100)) truth[y][x] = true;
    }
    list.end_frame();
    for (int y = -1; y <= 40; ++y)
        for (int x = -1; x <= 50; ++x) {
            const int32_t i = list.find(x, y);
            const bool expected = y >= 0 && y < 40 && x >= 0 && x < 50 && truth[y][x];
            REQUIRE((i >= 0) == expected);
            if (i >= 0) {
                REQUIRE(ep::x(list[static_cast<uint16_t>(i)]) == static_cast<uint32_t>(x));
                REQUIRE(ep::y(list[static_cast<uint16_t>(i)]) == static_cast<uint32_t>(y));
            }
        }
    // find_near gives find's answer whatever its probe remembers: walks either way along a row
    // (the probe carried from call to call, as PPHT does), jumps, and probes of other rows.
    RowProbe other_row;
    for (int y = -1; y <= 40; ++y) {
        RowProbe probe;
        for (int x = -1; x <= 50; ++x)
            REQUIRE(list.find_near(x, y, probe, true) == list.find(x, y));
        for (int x = 50; x >= -1; --x)
            REQUIRE(list.find_near(x, y, probe, false) == list.find(x, y));
        for (int x = -1; x <= 50; ++x)  // against the walk the probe expects
            REQUIRE(list.find_near(x, y, probe, false) == list.find(x, y));
        for (int k = 0; k < 400; ++k) {
            const int x = static_cast<int>(rng.below(k % 4 == 0 ? 2100 : 52)) - 1;
            const bool forward = rng.below(2) == 0;
            REQUIRE(list.find_near(x, y, probe, forward) == list.find(x, y));
            const int y2 = static_cast<int>(rng.below(42)) - 1;  // any row, one probe for all
            REQUIRE(list.find_near(x, y2, other_row, forward) == list.find(x, y2));
        }
    }
    // Fill past the capacity.
    REQUIRE(list.begin_frame(2) == Status::ok);
    list.begin_row(0);
    for (uint16_t k = 0; k < 310; ++k) list.push(static_cast<uint16_t>(k % 2000), 0, 0, 100);
    list.end_frame();
    REQUIRE(list.size() == 300);
    REQUIRE(list.dropped() == 10);
}

TEST_CASE("edge stage statuses: bad sizes, wrong rows, rows after the end", "[edges]") {
    EdgeList list = g_storage.view();
    gradient_word words[65] = {};
    REQUIRE(g_edges.begin_frame(0, 5, 40, list) == Status::bad_size);
    REQUIRE(g_edges.begin_frame(65, 5, 40, list) == Status::bad_size);
    REQUIRE(g_edges.begin_frame(10, 65, 40, list) == Status::bad_size);  // more rows than the list
    REQUIRE(g_edges.push_row(words, 10) == Status::not_in_frame);
    REQUIRE(g_edges.begin_frame(10, 2, 40, list) == Status::ok);
    REQUIRE(g_edges.push_row(words, 9) == Status::bad_row_length);
    REQUIRE(g_edges.push_row(words, 10) == Status::not_in_frame);
    REQUIRE(g_edges.begin_frame(10, 2, 40, list) == Status::ok);
    REQUIRE(g_edges.push_row(words, 10) == Status::ok);
    REQUIRE(g_edges.push_row(words, 10) == Status::ok);
    REQUIRE(g_edges.push_row(words, 10) == Status::not_in_frame);
}

TEST_CASE(
    "camera rows packed for NMS equal gradient words packed for NMS, at any width and threshold",
    "[edges]") {
    // The software path (gradient_nms_row: magnitudes first, directions only where a
    // magnitude reaches the threshold) against the word path (gradient_row, the FPGA block's
    // words, checked against the HDL by the vector tests) packed by pack_nms_row, with the
    // direction cleared below the threshold. Widths 1..70 cover the borders, every remainder
    // of the four-entry groups and rows shorter than one group; the pixels mix random values
    // with 0/255 runs (magnitude 510) and near-threshold steps.
    Pcg32 rng(77, 5);
    uint8_t rows[3][70];
    gradient_word words[70];
    uint16_t fast[72], reference[72];
    uint32_t entries = 0, with_direction = 0;
    for (uint16_t threshold : {1, 2, 39, 40, 41, 255, 509, 510}) {
        for (uint16_t width = 1; width <= 70; ++width) {
            for (int trial = 0; trial < 20; ++trial) {
                const uint32_t style = rng.below(3);
                for (auto& r : rows)
                    for (uint16_t x = 0; x < width; ++x)
                        r[x] =
                            style == 0 ? static_cast<uint8_t>(rng.below(256))
                            : style == 1
                                ? static_cast<uint8_t>(rng.below(2) * 255)
                                : static_cast<uint8_t>(
                                      100 + rng.below(2) * ((threshold / 2 + rng.below(3)) % 156));
                gradient_nms_row(rows[0], rows[1], rows[2], width, threshold, fast);
                gradient_row(rows[0], rows[1], rows[2], width, words);
                pack_nms_row(words, width, reference);
                for (uint16_t i = 1; i <= width; ++i)
                    if ((reference[i] & 0x1FFu) < threshold) reference[i] &= 0x1FFu;
                for (uint16_t i = 0; i < width + 2u; ++i) {
                    INFO("threshold " << threshold << " width " << width << " entry " << i);
                    REQUIRE(fast[i] == reference[i]);
                    with_direction += i >= 1 && i <= width && (reference[i] & 0x1FFu) >= threshold;
                }
                entries += width;
            }
        }
    }
    // Both kinds of entry occur, so the comparison tested the direction pass too.
    REQUIRE(with_direction > entries / 10);
    REQUIRE(with_direction < entries);
}

TEST_CASE(
    "a full edge list keeps the strongest edges whole and every other step of the weaker ones, in "
    "any raster order",
    "[edges]") {
    // 40 rows of 50 points with random magnitudes, the strongest in the last rows (a raster
    // order that fills the list with weak points first): 2000 pushes into a capacity of 300.
    EdgeListStorage<300, 40> storage;
    EdgeList list = storage.view();
    REQUIRE(list.begin_frame(40) == Status::ok);
    Pcg32 rng(31);
    uint32_t magnitude[40][50];
    for (uint16_t y = 0; y < 40; ++y) {
        list.begin_row(y);
        for (uint16_t x = 0; x < 50; ++x) {
            magnitude[y][x] = 40 + rng.below(200) + (y >= 30 ? 200u : 0u);
            list.push(x, y % 16u, 0, magnitude[y][x]);
        }
    }
    list.end_frame();
    const uint32_t floor = list.floor(), thin = list.thin_level();
    REQUIRE(floor > 40);
    REQUIRE(thin > floor);
    // The rule of edge_list.h, by hand: whole at or above thin, the even step from floor.
    // Direction y % 16: a gradient nearer x (bins 0-2, 6-10, 14, 15) steps along y, else x.
    auto kept = [&](uint32_t x, uint32_t y, uint32_t level) {
        const uint32_t d = y % 8u;
        const bool odd = (((d <= 2 || d >= 6) ? y : x) % 2u) == 1u;
        return magnitude[y][x] >= thin || (magnitude[y][x] >= level && !odd);
    };
    uint32_t expected = 0, one_step_lower = 0, whole = 0;
    for (uint16_t y = 0; y < 40; ++y)
        for (uint16_t x = 0; x < 50; ++x) {
            expected += kept(x, y, floor);
            one_step_lower += kept(x, y, floor - 2);
            whole += magnitude[y][x] >= thin;
            // Kept exactly by the rule, and found where it was pushed.
            const int32_t i = list.find(x, y);
            INFO("x " << x << " y " << y << " magnitude " << magnitude[y][x]);
            REQUIRE((i >= 0) == kept(x, y, floor));
            if (i >= 0) REQUIRE(ep::dir(list[static_cast<uint16_t>(i)]) == y % 16u);
        }
    CHECK(list.size() == expected);
    CHECK(list.size() <= 300);
    // Some points stay whole, and the floor rose no higher than needed: one step lower would
    // keep more than the 3/4 of the capacity a compaction leaves.
    CHECK(whole > 20);
    CHECK(one_step_lower > 225);
    CHECK(list.dropped() == 2000u - list.size());
}

TEST_CASE("a long weak edge keeps every other pixel in a full list of shorter, stronger edges",
          "[edges]") {
    // A board's side against a bright wall: a vertical edge of magnitude 60 down column 25 of
    // 40 rows (gradient along x: direction bin 0, steps along y), among 300 clutter points of
    // magnitude 100..199 (gradient along y: bin 4, steps along x) at random places. A list of
    // 300 that kept only its strongest points would keep clutter alone (300 points stronger
    // than the edge); thinned, the clutter's even steps and the edge's fit.
    EdgeListStorage<300, 40> storage;
    EdgeList list = storage.view();
    REQUIRE(list.begin_frame(40) == Status::ok);
    Pcg32 rng(5);
    bool clutter[40][50] = {};
    uint32_t clutter_points = 0;
    while (clutter_points < 300) {
        const uint32_t x = rng.below(50), y = rng.below(40);
        if (x == 25 || clutter[y][x]) continue;
        clutter[y][x] = true;
        ++clutter_points;
    }
    for (uint16_t y = 0; y < 40; ++y) {
        list.begin_row(y);
        for (uint16_t x = 0; x < 50; ++x) {
            if (x == 25) list.push(x, 0, 0, 60);
            if (clutter[y][x]) list.push(x, 4, 0, 100 + rng.below(100));
        }
    }
    list.end_frame();
    REQUIRE(list.dropped() > 0);
    REQUIRE(list.floor() <= 60);
    for (uint16_t y = 0; y < 40; ++y) {
        INFO("row " << y);
        CHECK((list.find(25, y) >= 0) == (y % 2 == 0));  // every other step of the edge
    }
}

TEST_CASE("a full edge list of equal magnitudes refuses the rest rather than choose among equals",
          "[edges]") {
    EdgeListStorage<100, 4> storage;
    EdgeList list = storage.view();
    REQUIRE(list.begin_frame(4) == Status::ok);
    list.begin_row(0);
    for (uint16_t x = 0; x < 100; ++x) REQUIRE(list.push(x, 0, 0, 80));
    list.begin_row(1);
    CHECK_FALSE(list.push(0, 0, 0, 80));  // no point is weaker than another: all stay
    CHECK(list.floor() == 82);
    CHECK(list.push(1, 0, 0, 90) == false);  // stronger, but the list is full of equals
    list.end_frame();
    CHECK(list.size() == 100);
    CHECK(list.dropped() == 2);
}

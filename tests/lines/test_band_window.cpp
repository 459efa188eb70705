// Tracking mode's window (lines/band_window.h): its spans worked by hand on a square, and the
// promise that a window changes nothing inside its bands: on boards composited onto real
// photographs, the edges found through a window are exactly the full frame's edges of the
// pixels the bands reach, from camera rows, from gradient rows and from the FPGA's edge beats.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "gradient/gradient_stage.h"
#include "io/image_io.h"
#include "lines/band_window.h"
#include "lines/edge_beat.h"
#include "lines/line_detector.h"
#include "scene/photo_board_scene.h"

using namespace qt;

namespace {

// The square (100, 50), (100, 150), (200, 150), (200, 50): sides left, bottom, right, top.
BandWindow square_window(int half_width, int reach) {
    const q16_16 x[4] = {q16_16::from_int(100), q16_16::from_int(100), q16_16::from_int(200),
                         q16_16::from_int(200)};
    const q16_16 y[4] = {q16_16::from_int(50), q16_16::from_int(150), q16_16::from_int(150),
                         q16_16::from_int(50)};
    BandWindow w;
    w.set_quad(x, y, q16_16::from_int(half_width), q16_16::from_int(reach), angle_from_deg(10));
    return w;
}

std::vector<std::pair<int, int>> spans_of(const BandWindow& w, int first, int last, int grow) {
    ColumnSpan s[BandWindow::kMaxSpans];
    const uint8_t n = w.spans(first, last, grow, 320, s);
    std::vector<std::pair<int, int>> out;
    for (uint8_t i = 0; i < n; ++i) out.emplace_back(s[i].begin, s[i].end);
    return out;
}

using Spans = std::vector<std::pair<int, int>>;

// The VGA build: its edge list (16 384 points) holds every edge of these QVGA frames.
LineDetectorVga g_lines;

// The frame's edges as the FPGA front end's beats (magnitude 255: above any threshold).
std::vector<uint8_t> beats_of(const std::vector<edge_point>& points, int width, int height) {
    std::vector<uint8_t> beats((points.size() + 1) * eb::kBytes);
    uint32_t i = 0;
    for (edge_point p : points)
        eb::store(eb::point(ep::x(p), ep::y(p), ep::dir(p), ep::delta16(p), 255), beats.data(),
                  i++);
    eb::store(
        eb::trailer(static_cast<uint32_t>(width - 1), static_cast<uint32_t>(height - 1), false),
        beats.data(), i);
    return beats;
}

// The edge points a window keeps of a frame's beats.
std::vector<edge_point> edges_from_beats(const std::vector<uint8_t>& beats, BandWindow* window) {
    REQUIRE(g_lines.begin_frame(320, 240, LineParams{}, window) == Status::ok);
    uint32_t used = 0;
    const uint32_t count = static_cast<uint32_t>(beats.size() / eb::kBytes);
    REQUIRE(g_lines.push_edge_beats(beats.data(), count, &used) == Status::ok);
    REQUIRE(used == count);
    REQUIRE(g_lines.edge_beats_done());
    std::vector<edge_point> points;
    for (uint16_t i = 0; i < g_lines.edges().size(); ++i) points.push_back(g_lines.edges()[i]);
    return points;
}

// The frame's edge points (raw words, states fresh), before PPHT consumes them.
std::vector<edge_point> edges_of(const io::GreyImage& img, BandWindow* window, bool gradient_rows) {
    REQUIRE(g_lines.begin_frame(static_cast<uint16_t>(img.width), static_cast<uint16_t>(img.height),
                                LineParams{}, window) == Status::ok);
    if (gradient_rows) {
        static GradientStage<640> gradient;
        REQUIRE(gradient.begin_frame(static_cast<uint16_t>(img.width),
                                     static_cast<uint16_t>(img.height)) == Status::ok);
        for (int y = 0; y < img.height; ++y)
            REQUIRE(gradient.push_row(&img.pixels[static_cast<size_t>(y * img.width)],
                                      static_cast<uint16_t>(img.width),
                                      [](uint16_t, const gradient_word* words, uint16_t n) {
                                          REQUIRE(g_lines.push_gradient_row(words, n) ==
                                                  Status::ok);
                                      }) == Status::ok);
    } else {
        for (int y = 0; y < img.height; ++y)
            REQUIRE(g_lines.push_row(&img.pixels[static_cast<size_t>(y * img.width)],
                                     static_cast<uint16_t>(img.width)) == Status::ok);
    }
    const EdgeList& list = g_lines.edges();
    REQUIRE(list.dropped() == 0);  // no capacity decisions: the full frame's list is all edges
    std::vector<edge_point> points;
    for (uint16_t i = 0; i < list.size(); ++i) points.push_back(list[i]);
    return points;
}

const std::vector<io::NamedImage>& photos() {
    static std::vector<io::NamedImage> loaded;
    static std::string error;
    if (loaded.empty() && error.empty()) io::read_image_folder(QT_PHOTO_DIR, loaded, error);
    INFO(error);
    REQUIRE(std::string(QT_PHOTOS_MISSING).empty());
    REQUIRE(!loaded.empty());
    return loaded;
}

}  // namespace

TEST_CASE("BandWindow: the columns its bands reach, worked by hand on a square", "[bands]") {
    const BandWindow w = square_window(4, 2);
    // Far from every band.
    CHECK(spans_of(w, 0, 0, 0).empty());
    CHECK(spans_of(w, 100, 100, 300).size() == 1);  // grown past the frame: clipped to it
    // The left side's band, x in [96, 104] (and 1/16 px more across), and the right's.
    CHECK(spans_of(w, 100, 100, 0) == Spans{{96, 105}, {196, 205}});
    // Rows 99..101, grown by a pixel.
    CHECK(spans_of(w, 99, 101, 1) == Spans{{95, 106}, {195, 206}});
    // Row 46: the top side's band only (y in [46, 54], x from 98 to 202 with its reach); the
    // left and right bands start at y = 48.
    CHECK(spans_of(w, 46, 46, 0) == Spans{{98, 203}});
    // Row 45: the square of pixel row 45 ends at 45.5 px, short of the band's 45.94.
    CHECK(spans_of(w, 45, 45, 0).empty());
    // Row 50: the top band and the two side bands overlap: one span.
    CHECK(spans_of(w, 50, 50, 0) == Spans{{96, 205}});
}

TEST_CASE("BandWindow: the lines along a side, worked by hand on a square", "[bands]") {
    const BandWindow w = square_window(4, 2);  // lines within 10 degrees of a side
    auto line = [](double x1, double y1, double x2, double y2) {
        Segment s{};
        s.x1 = q16_16::from_raw(std::llround(x1 * 65536));
        s.y1 = q16_16::from_raw(std::llround(y1 * 65536));
        s.x2 = q16_16::from_raw(std::llround(x2 * 65536));
        s.y2 = q16_16::from_raw(std::llround(y2 * 65536));
        return s;
    };
    CHECK(w.along_a_side(line(101, 60, 101, 140)));   // on the left side
    CHECK(w.along_a_side(line(150, 153, 110, 153)));  // 3 px below the bottom side, reversed
    // Turned 9 degrees (tan 9° = 0.158: 12.7 px over 80) and 10.5 degrees about its midpoint.
    CHECK(w.along_a_side(line(100 - 6.34, 60, 100 + 6.34, 140)));
    CHECK_FALSE(w.along_a_side(line(100 - 7.41, 60, 100 + 7.41, 140)));
    CHECK_FALSE(w.along_a_side(line(95, 100, 106, 100)));  // across the left band
    CHECK_FALSE(w.along_a_side(line(107, 60, 107, 140)));  // parallel, 7 px in: beyond 4 + 2
    CHECK(w.along_a_side(line(105.5, 60, 105.5, 140)));    // 5.5 px in: within 4 + 2
}

TEST_CASE("A window gives the full frame's edges wherever its bands reach, and none elsewhere",
          "[bands]") {
    int scenes = 0;
    for (int k = 0; k < 6; ++k) {
        scene::PhotoBoardOptions o;
        o.width = 320;
        o.height = 240;
        const auto& photo = photos()[static_cast<size_t>(k) % photos().size()].image;
        const scene::PhotoBoardScene s = scene::make_photo_board_scene(o, photo, 5000u + k);
        q16_16 x[4], y[4];
        for (int i = 0; i < 4; ++i) {
            // A prediction 3 px off the truth, as a tracker's is.
            x[i] = q16_16::from_raw(std::llround((s.corners[i].x + 3.0) * 65536.0));
            y[i] = q16_16::from_raw(std::llround((s.corners[i].y - 2.0) * 65536.0));
        }
        BandWindow window;
        window.set_quad(x, y, q16_16::from_int(12), q16_16::from_int(6), angle_from_deg(10));
        for (const bool gradient_rows : {false, true}) {
            INFO("scene " << k << (gradient_rows ? ", gradient rows" : ", camera rows"));
            const std::vector<edge_point> full = edges_of(s.image, nullptr, gradient_rows);
            std::vector<edge_point> expected;
            for (edge_point p : full) {
                ColumnSpan sp[BandWindow::kMaxSpans];
                const uint8_t n = window.spans(static_cast<int32_t>(ep::y(p)),
                                               static_cast<int32_t>(ep::y(p)), 0, 320, sp);
                bool inside = false;
                for (uint8_t i = 0; i < n; ++i)
                    inside = inside || (ep::x(p) >= sp[i].begin && ep::x(p) < sp[i].end);
                if (inside) expected.push_back(p);
            }
            const std::vector<edge_point> banded = edges_of(s.image, &window, gradient_rows);
            CHECK(banded.size() == expected.size());
            CHECK(banded == expected);
            // The bands hold the board's sides and leave out most of the frame.
            CHECK(expected.size() >= 200);
            CHECK(expected.size() < full.size());
            // The same frame's edges as the FPGA's beats: those outside the bands passed over.
            CHECK(edges_from_beats(beats_of(full, 320, 240), &window) == expected);
        }
        ++scenes;
    }
    CHECK(scenes == 6);
}

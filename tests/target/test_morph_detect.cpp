// Table III step 2 as the paper states it (core/target/morph_detect.h): top-hat and clustering,
// on regions drawn here whose clusters and centroids are worked out by hand.
#include <catch2/catch.hpp>

#include <vector>

#include "target/morph_detect.h"

using namespace qt;

namespace {

struct Image {
    int w, h;
    std::vector<uint8_t> p;
    Image(int w_, int h_, uint8_t v) : w(w_), h(h_), p(static_cast<size_t>(w_ * h_), v) {}
    void box(int x0, int y0, int bw, int bh, uint8_t v) {
        for (int y = y0; y < y0 + bh; ++y)
            for (int x = x0; x < x0 + bw; ++x) p[static_cast<size_t>(y * w + x)] = v;
    }
    PixelRegion region(int x0 = 0, int y0 = 0) const {
        PixelRegion r;
        r.pixels = p.data();
        r.stride = static_cast<uint32_t>(w);
        r.x0 = x0;
        r.y0 = y0;
        r.w = static_cast<uint16_t>(w);
        r.h = static_cast<uint16_t>(h);
        return r;
    }
};

}  // namespace

TEST_CASE("Morphological detection: a small bright blob, not the large bright field", "[morph]") {
    static MorphDetector<84, 84> det;
    Image img(60, 60, 50);
    img.box(10, 12, 5, 5, 200);    // the target: 5 × 5, centre (12, 14)
    img.box(35, 30, 25, 30, 200);  // a field wider than the element: the opening keeps it
    MorphParams p;
    p.element = 9;
    const MorphDetection d = det.detect(img.region(), 20, 20, 15, Polarity::bright, p);
    REQUIRE(d.found);
    // A uniform blob: the top-hat is 150 on each of its pixels, the centroid its centre.
    CHECK(d.x_q8 == 12 * 256);
    CHECK(d.y_q8 == 14 * 256);
    CHECK(d.area == 25);
    CHECK(d.clusters == 1);  // the field's top-hat is 0
    // The dark polarity sees no dark blob: nothing.
    CHECK_FALSE(det.detect(img.region(), 20, 20, 15, Polarity::dark, p).found);
}

TEST_CASE("Morphological detection: the nearest cluster, weighted centroid, area limits, offsets",
          "[morph]") {
    static MorphDetector<84, 84> det;
    Image img(50, 40, 180);
    img.box(5, 5, 3, 3, 40);    // dark 3 × 3 at centre (6, 6)
    img.box(30, 20, 4, 2, 60);  // dark 4 × 2 at centre (31.5, 20.5)
    img.box(32, 21, 2, 1, 20);  // darker inside: top-hat 160 on (32, 21), (33, 21), else 120
    MorphParams p;
    p.element = 7;
    // The region starts at frame pixel (100, 200): results are frame coordinates.
    MorphDetection d = det.detect(img.region(100, 200), 128, 218, 12, Polarity::dark, p);
    REQUIRE(d.found);
    CHECK(d.clusters == 1);  // the window (radius + element) holds only this one
    CHECK(d.area == 8);
    // Σt = 6·120 + 2·160 = 1040; Σt·x = 120·(30+31+32+33 + 30+31) + 160·(32+33) = 32840;
    // x = 31.5769… → 8084 / 256 after rounding 256·32840/1040 = 8083.69; Σt·y = 120·(4·20 + 2·21)
    // + 160·2·21 = 21360 → 20.5385 → 5257.85 → 5258.
    CHECK(d.x_q8 == (100 + 30) * 256 + 8084 - 30 * 256);
    CHECK(d.y_q8 == (200 + 20) * 256 + 5258 - 20 * 256);
    // Near the other one: it is chosen (area 9, centroid (6, 6)).
    d = det.detect(img.region(100, 200), 108, 208, 12, Polarity::dark, p);
    REQUIRE(d.found);
    CHECK(d.x_q8 == 106 * 256);
    CHECK(d.y_q8 == 206 * 256);
    // Areas 10..100 leave only clusters of 10 px or more: none.
    p.min_area = 10;
    CHECK_FALSE(det.detect(img.region(100, 200), 108, 208, 12, Polarity::dark, p).found);
    // A window holding neither centre (radius 1 about (120, 215)): nothing within it.
    p.min_area = 1;
    CHECK_FALSE(det.detect(img.region(100, 200), 120, 215, 1, Polarity::dark, p).found);
}

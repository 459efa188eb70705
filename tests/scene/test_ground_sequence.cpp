// The airborne ground sequence: its truth checked against what is rendered and against the
// pinhole model it documents, by code of its own here (projection, inversion, warping, template
// statistics), never against values the generator printed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "scene/ground_sequence.h"

using qt::io::GreyImage;
using qt::scene::GroundSequence;
using qt::scene::GroundSequenceConfig;
using qt::scene::GroundTruth;
using qt::scene::short_ground_sequence;

namespace {

struct Pt {
    double x, y;
};

Pt map(const double h[9], Pt p) {
    const double w = h[6] * p.x + h[7] * p.y + h[8];
    return {(h[0] * p.x + h[1] * p.y + h[2]) / w, (h[3] * p.x + h[4] * p.y + h[5]) / w};
}

// Inverse by cofactors divided by the determinant.
void inverse(const double m[9], double r[9]) {
    const double c0 = m[4] * m[8] - m[5] * m[7], c1 = m[5] * m[6] - m[3] * m[8],
                 c2 = m[3] * m[7] - m[4] * m[6];
    const double det = m[0] * c0 + m[1] * c1 + m[2] * c2;
    r[0] = c0 / det;
    r[1] = (m[2] * m[7] - m[1] * m[8]) / det;
    r[2] = (m[1] * m[5] - m[2] * m[4]) / det;
    r[3] = c1 / det;
    r[4] = (m[0] * m[8] - m[2] * m[6]) / det;
    r[5] = (m[2] * m[3] - m[0] * m[5]) / det;
    r[6] = c2 / det;
    r[7] = (m[1] * m[6] - m[0] * m[7]) / det;
    r[8] = (m[0] * m[4] - m[1] * m[3]) / det;
}

double bilinear(const GreyImage& img, double x, double y) {
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    const auto at = [&](int xx, int yy) { return double(img.at(xx, yy)); };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// Mean |frame − previous frame warped by h| over pixels whose source lies 2 px inside the previous
// image and that are more than `keep_out` px from `avoid` (the vehicle, which moves over the
// ground).
double warp_error(const GreyImage& prev, const GreyImage& cur, const double h[9], Pt avoid,
                  double keep_out) {
    double hinv[9];
    inverse(h, hinv);
    double sum = 0;
    int n = 0;
    for (int y = 2; y < cur.height - 2; ++y)
        for (int x = 2; x < cur.width - 2; ++x) {
            if (std::hypot(x - avoid.x, y - avoid.y) < keep_out) continue;
            const Pt s = map(hinv, {double(x), double(y)});
            if (s.x < 2 || s.y < 2 || s.x > prev.width - 3 || s.y > prev.height - 3) continue;
            sum += std::fabs(cur.at(x, y) - bilinear(prev, s.x, s.y));
            ++n;
        }
    REQUIRE(n > cur.width * cur.height / 2);
    return sum / n;
}

struct Window {
    int x0, y0, x1, y1;  // inclusive, clipped to the image
};

Window window(const GreyImage& img, double cx, double cy, double half_w, double half_h) {
    return {std::max(0, int(std::floor(cx - half_w))), std::max(0, int(std::floor(cy - half_h))),
            std::min(img.width - 1, int(std::ceil(cx + half_w))),
            std::min(img.height - 1, int(std::ceil(cy + half_h)))};
}

// Centroid of the pixels of `win` where pred(x, y) holds; count in n.
template <class Pred>
Pt centroid(const Window& win, Pred pred, int& n) {
    double sx = 0, sy = 0;
    n = 0;
    for (int y = win.y0; y <= win.y1; ++y)
        for (int x = win.x0; x <= win.x1; ++x)
            if (pred(x, y)) {
                sx += x;
                sy += y;
                ++n;
            }
    return n ? Pt{sx / n, sy / n} : Pt{-1e9, -1e9};
}

// How far the point lies outside the image (≤ 0: inside), px.
double outside(const GroundSequenceConfig& c, double x, double y) {
    return std::max({-0.5 - x, x - (c.width - 0.5), -0.5 - y, y - (c.height - 0.5)});
}

uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
    uint64_t h = 0xCBF29CE484222325ULL;
    for (uint8_t b : bytes) h = (h ^ b) * 0x100000001B3ULL;
    return h;
}

GroundSequenceConfig without_vehicle(GroundSequenceConfig c) {
    c.draw_target = false;
    return c;
}

}  // namespace

TEST_CASE("ground sequence: the truth homographies are a pinhole camera's over the ground",
          "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence seq(c);
    const GroundTruth first = seq.truth(0);
    for (int i = 0; i < 9; ++i) CHECK(first.h_from_previous[i] == (i % 4 == 0 ? 1.0 : 0.0));

    const double f = c.focal_px, cx = (c.width - 1) / 2.0, cy = (c.height - 1) / 2.0;
    const Pt probes[5] = {
        {0, 0}, {c.width - 1.0, 0}, {0, c.height - 1.0}, {c.width - 1.0, c.height - 1.0}, {cx, cy}};
    GroundTruth prev = first;
    for (int frame = 1; frame < seq.frames(); ++frame) {
        const GroundTruth t = seq.truth(frame);
        CHECK(t.h_from_previous[8] == 1.0);
        // K⁻¹·G = [r1 r2 t]·s: two orthogonal columns of equal length (a rotation's).
        const double* g = t.h_ground_to_image;
        double r1[3] = {(g[0] - cx * g[6]) / f, (g[3] - cy * g[6]) / f, g[6]};
        double r2[3] = {(g[1] - cx * g[7]) / f, (g[4] - cy * g[7]) / f, g[7]};
        const double n1 = std::sqrt(r1[0] * r1[0] + r1[1] * r1[1] + r1[2] * r1[2]);
        const double n2 = std::sqrt(r2[0] * r2[0] + r2[1] * r2[1] + r2[2] * r2[2]);
        CHECK(n1 == Approx(1).epsilon(1e-9));  // third row = depth in metres: unit scale
        CHECK(n2 == Approx(1).epsilon(1e-9));
        CHECK(std::fabs(r1[0] * r2[0] + r1[1] * r2[1] + r1[2] * r2[2]) < 1e-9);

        // Ground points seen in the previous frame map through h_from_previous onto their
        // projection in this frame.
        double ginv[9];
        inverse(prev.h_ground_to_image, ginv);
        for (const Pt& p : probes) {
            const Pt ground = map(ginv, p);
            const double depth = g[6] * ground.x + g[7] * ground.y + g[8];
            CHECK(depth > 0);  // in front of the camera
            const Pt expected = map(g, ground);
            const Pt got = map(t.h_from_previous, p);
            CHECK(got.x == Approx(expected.x).margin(1e-6));
            CHECK(got.y == Approx(expected.y).margin(1e-6));
        }
        prev = t;
    }
}

TEST_CASE("ground sequence: the rendered ground moves by the truth homography",
          "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence seq(c);
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int frame : {1, 5, 25, 45, 60}) {  // no flare in these or the frames before
        const GroundTruth t = seq.truth(frame);
        const GreyImage prev = seq.render(frame - 1), cur = seq.render(frame);
        const double err = warp_error(prev, cur, t.h_from_previous, {t.target_x, t.target_y}, 20);
        const double still = warp_error(prev, cur, identity, {t.target_x, t.target_y}, 20);
        INFO("frame " << frame << ": warped " << err << ", not warped " << still);
        CHECK(err < 5);  // noise (2 levels in each frame) and the blur of interpolation
        CHECK(err < 0.5 * still);
    }
}

TEST_CASE("ground sequence: the vehicle is rendered where the truth puts it", "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence seq(c), bare(without_vehicle(c));
    int checked = 0;
    for (int frame = 0; frame < seq.frames(); frame += 3) {
        const GroundTruth t = seq.truth(frame);
        if (!t.in_view || t.occluded) continue;
        ++checked;
        INFO("frame " << frame << " truth (" << t.target_x << ", " << t.target_y << ") box "
                      << t.target_w << "×" << t.target_h);
        const GreyImage img = seq.render(frame), ground = bare.render(frame);

        // The vehicle's own pixels, by difference with the same frame rendered without it (the
        // noise is the same): centred on the truth, as big as its box.
        const Window wide = window(img, t.target_x, t.target_y, 20, 20);
        int n = 0;
        const Pt diff = centroid(
            wide, [&](int x, int y) { return std::abs(img.at(x, y) - ground.at(x, y)) > 20; }, n);
        CHECK(diff.x == Approx(t.target_x).margin(1.0));
        CHECK(diff.y == Approx(t.target_y).margin(1.0));
        CHECK(n <= (t.target_w + 1) * (t.target_h + 1));
        CHECK(n >= 20);
        int elsewhere = 0;  // and nowhere else
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            const int x = int(i % img.width), y = int(i / img.width);
            if (std::fabs(x - t.target_x) > t.target_w / 2.0 + 1.5 ||
                std::fabs(y - t.target_y) > t.target_h / 2.0 + 1.5)
                elsewhere += img.pixels[i] != ground.pixels[i];
        }
        CHECK(elsewhere == 0);

        // In the frame itself: the bright roof (brighter than any ground) is centred on the truth.
        const Pt roof = centroid(
            wide, [&](int x, int y) { return img.at(x, y) >= 222; }, n);
        CHECK(n >= 6);
        CHECK(roof.x == Approx(t.target_x).margin(1.0));
        CHECK(roof.y == Approx(t.target_y).margin(1.0));

        // The box stands out from the ring around it (dark body, bright roof).
        const Window box =
            window(img, t.target_x, t.target_y, t.target_w / 2.0 - 1, t.target_h / 2.0 - 1);
        const Window ring =
            window(img, t.target_x, t.target_y, t.target_w / 2.0 + 6, t.target_h / 2.0 + 6);
        double ring_sum = 0;
        int ring_n = 0;
        for (int y = ring.y0; y <= ring.y1; ++y)
            for (int x = ring.x0; x <= ring.x1; ++x)
                if (x < box.x0 - 2 || x > box.x1 + 2 || y < box.y0 - 2 || y > box.y1 + 2) {
                    ring_sum += img.at(x, y);
                    ++ring_n;
                }
        const double ring_mean = ring_sum / ring_n;
        double dev = 0;
        int box_n = 0;
        for (int y = box.y0; y <= box.y1; ++y)
            for (int x = box.x0; x <= box.x1; ++x, ++box_n)
                dev += std::fabs(img.at(x, y) - ring_mean);
        CHECK(dev / box_n > 30);
        // About 8–14 px.
        CHECK(std::max(t.target_w, t.target_h) >= 8);
        CHECK(std::max(t.target_w, t.target_h) <= 17);
    }
    CHECK(checked >= 12);
}

TEST_CASE("ground sequence: the vehicle leaves the image for the out-of-view spell and comes back",
          "[ground_sequence]") {
    for (const GroundSequenceConfig& c : {short_ground_sequence(), GroundSequenceConfig{}}) {
        const GroundSequence seq(c);
        const int end = c.out_of_view_start + c.out_of_view_frames;
        double deepest = 0;
        for (int frame = 0; frame < seq.frames(); ++frame) {
            const GroundTruth t = seq.truth(frame);
            INFO("frame " << frame << " of " << c.frames);
            const bool spell = frame >= c.out_of_view_start && frame < end;
            CHECK(t.in_view == !spell);
            // The box from the truth's centre and size agrees (to the rounding of its size).
            const double box_out =
                std::max(outside(c, t.target_x - t.target_w / 2.0, t.target_y - t.target_h / 2.0),
                         outside(c, t.target_x + t.target_w / 2.0, t.target_y + t.target_h / 2.0));
            if (spell)
                CHECK(box_out > -1);
            else
                CHECK(box_out < 1);
            deepest = std::max(deepest, outside(c, t.target_x, t.target_y));
        }
        CHECK(deepest >=
              (c.out_of_view_frames >= 100 ? 60 : 25));  // the centre, beyond the border, px

        // Well inside the spell nothing of the vehicle is drawn; just before and after it is.
        const GroundSequence bare(without_vehicle(c));
        const int middle = c.out_of_view_start + c.out_of_view_frames / 2;
        CHECK(seq.render(middle).pixels == bare.render(middle).pixels);
        CHECK(seq.render(c.out_of_view_start - 1).pixels !=
              bare.render(c.out_of_view_start - 1).pixels);
        CHECK(seq.render(end).pixels != bare.render(end).pixels);
    }
}

TEST_CASE("ground sequence: the flare covers the vehicle in the occlusion frames only",
          "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence seq(c), bare(without_vehicle(c));
    for (int frame = 0; frame < seq.frames(); ++frame) {
        const GroundTruth t = seq.truth(frame);
        INFO("frame " << frame);
        CHECK(t.occluded ==
              (frame >= c.occlusion_start && frame < c.occlusion_start + c.occlusion_frames));
    }
    for (int frame = c.occlusion_start; frame < c.occlusion_start + c.occlusion_frames; ++frame) {
        const GroundTruth t = seq.truth(frame);
        INFO("frame " << frame);
        REQUIRE(t.in_view);
        const GreyImage img = seq.render(frame), ground = bare.render(frame);
        const Window box =
            window(img, t.target_x, t.target_y, t.target_w / 2.0 + 1, t.target_h / 2.0 + 1);
        for (int y = box.y0; y <= box.y1; ++y)
            for (int x = box.x0; x <= box.x1; ++x) {
                CHECK(img.at(x, y) >= 240);              // saturated, like the flare's core
                CHECK(img.at(x, y) == ground.at(x, y));  // nothing of the vehicle shows
            }
    }
    GroundSequenceConfig none = c;
    none.occlusion_frames = 0;
    const GroundSequence clear(none);
    for (int frame = 0; frame < clear.frames(); ++frame) CHECK_FALSE(clear.truth(frame).occluded);
}

TEST_CASE("ground sequence: rendering is deterministic and the same on every platform",
          "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence a(c), b(c);
    const GreyImage first = a.render(20);
    CHECK(first.pixels == b.render(20).pixels);
    CHECK(first.pixels == a.render(20).pixels);
    GroundSequenceConfig other = c;
    other.seed = 2;
    CHECK(GroundSequence(other).render(20).pixels != first.pixels);
    CHECK(a.render(21).pixels != first.pixels);
    // Golden FNV-1a of two frames, computed on x86-64; the aarch64 preset runs this too. A
    // deliberate change of the generator changes these.
    CHECK(fnv1a(first.pixels) == 0x837e779277c0b0fcULL);
    CHECK(fnv1a(a.render(c.occlusion_start + 2).pixels) == 0x86b983d3a28964edULL);
}

TEST_CASE("ground sequence: the ground is textured everywhere, with corners", "[ground_sequence]") {
    const GroundSequenceConfig c = short_ground_sequence();
    const GroundSequence seq(c);
    for (int frame : {0, 20, 40, 60}) {
        const GreyImage img = seq.render(frame);
        INFO("frame " << frame);
        // 16×16 blocks whose standard deviation is well above the noise's.
        int blocks = 0, textured = 0;
        for (int by = 0; by + 16 <= img.height; by += 16)
            for (int bx = 0; bx + 16 <= img.width; bx += 16, ++blocks) {
                double s = 0, s2 = 0;
                for (int y = by; y < by + 16; ++y)
                    for (int x = bx; x < bx + 16; ++x) {
                        s += img.at(x, y);
                        s2 += double(img.at(x, y)) * img.at(x, y);
                    }
                const double mean = s / 256, sd = std::sqrt(std::max(0.0, s2 / 256 - mean * mean));
                if (sd >= 8) ++textured;
            }
        CHECK(textured >= 0.9 * blocks);

        // Corners: the smaller eigenvalue of the structure tensor over 5×5 (central differences,
        // grey levels / px); 16×16 cells holding a strong one (300 cells at 320×240).
        const int w = img.width, h = img.height;
        std::vector<double> gxx(size_t(w) * h), gyy(gxx.size()), gxy(gxx.size());
        for (int y = 1; y < h - 1; ++y)
            for (int x = 1; x < w - 1; ++x) {
                const double gx = (img.at(x + 1, y) - img.at(x - 1, y)) / 2.0,
                             gy = (img.at(x, y + 1) - img.at(x, y - 1)) / 2.0;
                gxx[size_t(y) * w + x] = gx * gx;
                gyy[size_t(y) * w + x] = gy * gy;
                gxy[size_t(y) * w + x] = gx * gy;
            }
        int cells = 0, cornered = 0;
        for (int cy = 0; cy + 16 <= h; cy += 16)
            for (int cx = 0; cx + 16 <= w; cx += 16, ++cells) {
                double best = 0;
                for (int y = std::max(cy, 3); y < std::min(cy + 16, h - 3); ++y)
                    for (int x = std::max(cx, 3); x < std::min(cx + 16, w - 3); ++x) {
                        double a = 0, b = 0, d = 0;
                        for (int v = -2; v <= 2; ++v)
                            for (int u = -2; u <= 2; ++u) {
                                const size_t i = size_t(y + v) * w + x + u;
                                a += gxx[i];
                                b += gyy[i];
                                d += gxy[i];
                            }
                        best =
                            std::max(best, (a + b) / 2 - std::sqrt((a - b) * (a - b) / 4 + d * d));
                    }
                if (best >= 1000) ++cornered;  // noise alone: ~50
            }
        CHECK(cornered >= 0.9 * cells);
    }
}

TEST_CASE("ground sequence: inter-frame image motion is bounded", "[ground_sequence]") {
    for (uint64_t seed : {1u, 2u, 3u}) {
        for (GroundSequenceConfig c : {short_ground_sequence(), GroundSequenceConfig{}}) {
            c.seed = seed;
            const GroundSequence seq(c);
            for (int frame = 1; frame < seq.frames(); ++frame) {
                const GroundTruth t = seq.truth(frame);
                double most = 0;
                for (int y = 0; y < c.height; y += 17)
                    for (int x = 0; x < c.width; x += 17) {
                        const Pt q = map(t.h_from_previous, {double(x), double(y)});
                        most = std::max(most, std::hypot(q.x - x, q.y - y));
                    }
                // Rotation: the turn of a short horizontal segment at the centre, degrees.
                const double cx = (c.width - 1) / 2.0, cy = (c.height - 1) / 2.0;
                const Pt p0 = map(t.h_from_previous, {cx, cy}),
                         p1 = map(t.h_from_previous, {cx + 10, cy});
                const double turn =
                    std::fabs(std::atan2(p1.y - p0.y, p1.x - p0.x)) * 180 / 3.14159265358979;
                INFO("seed " << seed << " frame " << frame << " of " << c.frames);
                CHECK(most <= 7.0);
                CHECK(turn <= 1.0);
            }
        }
    }
}

TEST_CASE("ground sequence: bad configurations are refused", "[ground_sequence]") {
    GroundSequenceConfig c = short_ground_sequence();
    c.frames = 0;
    CHECK_THROWS_AS(GroundSequence(c), std::invalid_argument);
    c = short_ground_sequence();
    c.width = 8;
    CHECK_THROWS_AS(GroundSequence(c), std::invalid_argument);
    const GroundSequence seq(short_ground_sequence());
    CHECK_THROWS_AS(seq.truth(seq.frames()), std::out_of_range);
    CHECK_THROWS_AS(seq.render(-1), std::out_of_range);

    GroundSequenceConfig never = short_ground_sequence();
    never.out_of_view_frames = 0;
    const GroundSequence stays(never);
    for (int frame = 0; frame < stays.frames(); ++frame) CHECK(stays.truth(frame).in_view);
}

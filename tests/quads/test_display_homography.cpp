// The display homography against a double-precision direct linear transform (the 8 × 8 system
// of the four correspondences, solved by Gaussian elimination) and a hand-worked affine case.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <utility>

#include "base/prng.h"
#include "quads/display_homography.h"
#include "support/segment_reference.h"

using namespace qt;
using qt::ref::from_q16;
using qt::ref::to_q16;

namespace {

struct P {
    double x, y;
};

// H (h33 = 1) with H·src[i] ~ dst[i], from the DLT equations
//   x = h11 u + h12 v + h13 − h31 u x − h32 v x, and the same for y.
std::array<double, 9> dlt(const P src[4], const P dst[4]) {
    double a[8][9] = {};
    for (int i = 0; i < 4; ++i) {
        const double u = src[i].x, v = src[i].y, x = dst[i].x, y = dst[i].y;
        const double r1[9] = {u, v, 1, 0, 0, 0, -u * x, -v * x, x};
        const double r2[9] = {0, 0, 0, u, v, 1, -u * y, -v * y, y};
        for (int k = 0; k < 9; ++k) {
            a[2 * i][k] = r1[k];
            a[2 * i + 1][k] = r2[k];
        }
    }
    for (int c = 0; c < 8; ++c) {  // partial pivoting
        int piv = c;
        for (int r = c + 1; r < 8; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
        for (int k = 0; k < 9; ++k) std::swap(a[c][k], a[piv][k]);
        for (int r = 0; r < 8; ++r) {
            if (r == c) continue;
            const double f = a[r][c] / a[c][c];
            for (int k = c; k < 9; ++k) a[r][k] -= f * a[c][k];
        }
    }
    std::array<double, 9> h{};
    for (int i = 0; i < 8; ++i) h[i] = a[i][8] / a[i][i];
    h[8] = 1;
    return h;
}

P apply(const std::array<double, 9>& h, double u, double v) {
    const double w = h[6] * u + h[7] * v + h[8];
    return {(h[0] * u + h[1] * v + h[2]) / w, (h[3] * u + h[4] * v + h[5]) / w};
}

}  // namespace

TEST_CASE("display homography of an axis-aligned rectangle is a scale and a shift",
          "[homography]") {
    // Display 100 × 50 onto the rectangle (10, 20) – (210, 120): x = 2u + 10, y = 2v + 20.
    const Point16 corners[4] = {{to_q16(10), to_q16(20)},
                                {to_q16(10), to_q16(120)},
                                {to_q16(210), to_q16(120)},
                                {to_q16(210), to_q16(20)}};
    DisplayHomography h;
    REQUIRE(display_homography(corners, 100, 50, h));
    CHECK(h.a == q12_20::from_int(2));
    CHECK(h.e == q12_20::from_int(2));
    CHECK(h.b.raw == 0);
    CHECK(h.d.raw == 0);
    CHECK(h.c == q16_16::from_int(10));
    CHECK(h.f == q16_16::from_int(20));
    CHECK(h.g.raw == 0);
    CHECK(h.h.raw == 0);
    Point16 p;
    REQUIRE(map_display_point(h, q16_16::from_int(25), q16_16::from_int(40), p));
    CHECK(p.x == q16_16::from_int(60));
    CHECK(p.y == q16_16::from_int(100));
}

TEST_CASE("display homography agrees with a double-precision DLT on perspective boards",
          "[homography]") {
    Pcg32 rng(11, 3);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * (rng.next() / 4294967296.0); };
    double worst = 0;
    for (int trial = 0; trial < 500; ++trial) {
        // A convex quadrangle: a rectangle with each corner moved up to 25 % of its size.
        const double cx = u(200, 440), cy = u(150, 330), hw = u(40, 180), hh = u(30, 130);
        const P img[4] = {{cx - hw + u(-.25, .25) * hw, cy - hh + u(-.25, .25) * hh},   // TL
                          {cx - hw + u(-.25, .25) * hw, cy + hh + u(-.25, .25) * hh},   // BL
                          {cx + hw + u(-.25, .25) * hw, cy + hh + u(-.25, .25) * hh},   // BR
                          {cx + hw + u(-.25, .25) * hw, cy - hh + u(-.25, .25) * hh}};  // TR
        Point16 corners[4];
        P exact[4];  // the corners as the fixed-point code sees them (rounded to 2^-16 px)
        for (int i = 0; i < 4; ++i) {
            corners[i] = {to_q16(img[i].x), to_q16(img[i].y)};
            exact[i] = {from_q16(corners[i].x), from_q16(corners[i].y)};
        }
        const uint16_t W = 1024, H = 768;
        const P disp[4] = {{0, 0}, {0, double(H)}, {double(W), double(H)}, {double(W), 0}};
        const auto ref = dlt(disp, exact);
        DisplayHomography h;
        REQUIRE(display_homography(corners, W, H, h));
        for (int gy = 0; gy <= 8; ++gy)
            for (int gx = 0; gx <= 8; ++gx) {
                const double du = W * gx / 8.0, dv = H * gy / 8.0;
                Point16 p;
                REQUIRE(map_display_point(h, to_q16(du), to_q16(dv), p));
                const P r = apply(ref, du, dv);
                worst = std::fmax(worst, std::hypot(from_q16(p.x) - r.x, from_q16(p.y) - r.y));
            }
    }
    // Corners are taken to 1/256 px, the matrix to ~1e-6: a hundredth of a pixel bounds the rest.
    CHECK(worst < 0.01);
}

TEST_CASE("display homography refuses what it cannot represent", "[homography]") {
    const Point16 ok[4] = {{to_q16(10), to_q16(10)},
                           {to_q16(10), to_q16(90)},
                           {to_q16(110), to_q16(90)},
                           {to_q16(110), to_q16(10)}};
    DisplayHomography h;
    CHECK_FALSE(display_homography(ok, 0, 768, h));
    const Point16 far[4] = {{to_q16(10), to_q16(10)},
                            {to_q16(10), to_q16(90)},
                            {to_q16(3000), to_q16(90)},
                            {to_q16(110), to_q16(10)}};
    CHECK_FALSE(display_homography(far, 1024, 768, h));
    const Point16 collinear[4] = {{to_q16(10), to_q16(10)},
                                  {to_q16(20), to_q16(20)},
                                  {to_q16(30), to_q16(30)},
                                  {to_q16(40), to_q16(40)}};
    CHECK_FALSE(display_homography(collinear, 1024, 768, h));
    REQUIRE(display_homography(ok, 1024, 768, h));
    Point16 p;
    CHECK_FALSE(map_display_point(h, q16_16::from_int(5000), q16_16::from_int(0), p));
}

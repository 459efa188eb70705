// The template's pose (core/target/float/template_pose.h): the warp against exact pixel
// permutations and against a smooth texture rendered in double precision at the warped pose, its
// refusals, the negligible-move test by hand, and the pose's Jacobian after two rotations.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "support/smooth_texture.h"
#include "target/float/template_pose.h"
#include "target/ncc_match.h"

using namespace qt;
using qt::test::smooth_texture;

namespace {

// The texture about the template's centre as the linear map m (row-major 2 × 2, double) shows
// it: pixel p holds smooth_texture(c + m⁻¹(p − c)), rounded.
std::vector<uint8_t> render(int w, int h, const double m[4]) {
    const double det = m[0] * m[3] - m[1] * m[2];
    const double a = m[3] / det, b = -m[1] / det, c = -m[2] / det, d = m[0] / det;
    const double cx = 0.5 * (w - 1), cy = 0.5 * (h - 1);
    std::vector<uint8_t> img(static_cast<size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = x - cx, dy = y - cy;
            img[static_cast<size_t>(y * w + x)] = static_cast<uint8_t>(
                std::lround(smooth_texture(cx + a * dx + b * dy, cy + c * dx + d * dy)));
        }
    return img;
}

int32_t ncc(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int w, int h) {
    return ncc_q15(a.data(), static_cast<uint32_t>(w), b.data(), static_cast<uint32_t>(w),
                   static_cast<uint16_t>(w), static_cast<uint16_t>(h))
        .q15;
}

}  // namespace

TEST_CASE("warp_template: the identity and quarter turns are exact pixel permutations",
          "[template][pose]") {
    const int w = 7, h = 7;
    std::vector<uint8_t> in(w * h), out(w * h);
    for (int i = 0; i < w * h; ++i) in[static_cast<size_t>(i)] = static_cast<uint8_t>(i * 5 + 3);
    const float identity[4] = {1, 0, 0, 1};
    REQUIRE(warp_template(in.data(), w, h, identity, out.data()));
    CHECK(out == in);
    // J = [0 −1; 1 0] turns the image a quarter (x right, y down: (1, 0) → (0, 1)); J⁻¹ = [0 1;
    // −1 0], so out(x, y) = in(c + (y − c), c − (x − c)) = in(y, 6 − x) about c = 3.
    const float quarter[4] = {0, -1, 1, 0};
    REQUIRE(warp_template(in.data(), w, h, quarter, out.data()));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            INFO("(" << x << ", " << y << ")");
            CHECK(out[static_cast<size_t>(y * w + x)] == in[static_cast<size_t>((6 - x) * w + y)]);
        }
    // A half turn on an even side: about the half-pixel centre (2.5, 1.5) of 6 × 4, out(x, y) =
    // in(5 − x, 3 − y).
    const int w2 = 6, h2 = 4;
    std::vector<uint8_t> in2(w2 * h2), out2(w2 * h2);
    for (int i = 0; i < w2 * h2; ++i) in2[static_cast<size_t>(i)] = static_cast<uint8_t>(i * 11);
    const float half[4] = {-1, 0, 0, -1};
    REQUIRE(warp_template(in2.data(), w2, h2, half, out2.data()));
    for (int y = 0; y < h2; ++y)
        for (int x = 0; x < w2; ++x)
            CHECK(out2[static_cast<size_t>(y * w2 + x)] ==
                  in2[static_cast<size_t>((3 - y) * w2 + 5 - x)]);
}

TEST_CASE("warp_template matches the texture rendered at the warped pose, and scores it better",
          "[template][pose]") {
    // A 15 × 15 template of the smooth texture; the camera turns it by 12° and scales it by 1.06
    // (with a shear), and the same texture is rendered at that pose in double precision. Pixels
    // whose source lies inside the template must agree within 4 grey levels: bilinear
    // interpolation errs by at most (max |f_xx| + max |f_yy|)/8 = 27.1/8 ≈ 3.4 on this texture,
    // and the roundings of the cut, the warp and the view add at most 1.5: under 5 in all
    // (measured 3). The warped template must score that view
    // better than the template as cut, and above 0.95.
    const int w = 15, h = 15;
    const double identity[4] = {1, 0, 0, 1};
    const std::vector<uint8_t> cut = render(w, h, identity);
    const double t = 12.0 * 3.14159265358979 / 180.0, s = 1.06;
    const double m[4] = {s * std::cos(t), -s * std::sin(t) + 0.03, s * std::sin(t),
                         s * std::cos(t)};
    const std::vector<uint8_t> view = render(w, h, m);
    const float j[4] = {static_cast<float>(m[0]), static_cast<float>(m[1]),
                        static_cast<float>(m[2]), static_cast<float>(m[3])};
    std::vector<uint8_t> warped(w * h);
    REQUIRE(warp_template(cut.data(), w, h, j, warped.data()));
    const double det = m[0] * m[3] - m[1] * m[2];
    const double cx = 0.5 * (w - 1), cy = 0.5 * (h - 1);
    int inside = 0;
    double worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = x - cx, dy = y - cy;
            const double sx = cx + (m[3] * dx - m[1] * dy) / det,
                         sy = cy + (-m[2] * dx + m[0] * dy) / det;
            if (sx < 0 || sy < 0 || sx > w - 1 || sy > h - 1) continue;
            ++inside;
            const size_t i = static_cast<size_t>(y * w + x);
            worst = std::max(worst, std::abs(static_cast<double>(warped[i]) - view[i]));
        }
    INFO("worst difference " << worst << " over " << inside << " pixels");
    CHECK(inside > w * h / 2);
    CHECK(worst <= 4.0);
    const int32_t as_cut = ncc(cut, view, w, h), as_warped = ncc(warped, view, w, h);
    INFO("NCC as cut " << as_cut << ", warped " << as_warped << " (Q15)");
    CHECK(as_warped > as_cut);
    CHECK(as_warped > 31000);  // 0.95
}

TEST_CASE("warp_template refuses a degenerate or implausible map and leaves out untouched",
          "[template][pose]") {
    const uint8_t in[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    uint8_t out[9] = {};
    const float shrink[4] = {0.49f, 0, 0, 0.5f};  // det 0.245 < 1/4
    const float grow[4] = {2.01f, 0, 0, 2.0f};    // det 4.02 > 4
    const float nan[4] = {std::nanf(""), 0, 0, 1};
    const float shear[4] = {1, 17, 0, 1};  // det 1, but j⁻¹ has −17
    for (const float* j : {shrink, grow, nan, shear}) CHECK_FALSE(warp_template(in, 3, 3, j, out));
    for (uint8_t v : out) CHECK(v == 0);
    const float edge_small[4] = {0.5f, 0, 0, 0.5f}, edge_large[4] = {2, 0, 0, 2};  // det 1/4, 4
    CHECK(warp_template(in, 3, 3, edge_small, out));
    CHECK(warp_template(in, 3, 3, edge_large, out));
}

TEST_CASE("warp_negligible: no pixel of the template moves by 1/16 px", "[template][pose]") {
    const float identity[4] = {1, 0, 0, 1};
    CHECK(warp_negligible(identity, 15, 15));
    // A 3-wide template's corners are 1 px from its centre: a scale of 1 + 1/32 moves them
    // 1/32 px, 1 + 1/8 moves them 1/8 px.
    const float small[4] = {1.0f + 1.0f / 32, 0, 0, 1}, large[4] = {1.0f + 1.0f / 8, 0, 0, 1};
    CHECK(warp_negligible(small, 3, 3));
    CHECK_FALSE(warp_negligible(large, 3, 3));
    // The same 1/32 on a 15-wide template moves its corners 7/32 px.
    CHECK_FALSE(warp_negligible(small, 15, 15));
    // A shear moves x by j1 · (h − 1)/2: 0.01 · 3 = 0.03 px on 7 rows, 0.01 · 7 = 0.07 on 15.
    const float shear[4] = {1, 0.01f, 0, 1};
    CHECK(warp_negligible(shear, 3, 7));
    CHECK_FALSE(warp_negligible(shear, 3, 15));
}

TEST_CASE("TemplatePose: two rotations about the centre give the sum's Jacobian there",
          "[template][pose]") {
    // A rotation by θ about (cx, cy) as a homography: [R, (I − R)c; 0 0 1]; after θ1 then θ2 the
    // Jacobian at c is R(θ1 + θ2) whatever the centre.
    auto rotation = [](double th, double cx, double cy) {
        const double c = std::cos(th), s = std::sin(th);
        Homography r;
        const double m[9] = {c, -s, cx - c * cx + s * cy, s, c, cy - s * cx - c * cy, 0, 0, 1};
        for (int i = 0; i < 9; ++i) r.m[i] = static_cast<float>(m[i]);
        return r;
    };
    TemplatePose pose;
    pose.reset(40.0f, 30.0f);
    pose.follow(rotation(0.10, 40, 30));
    pose.follow(rotation(0.05, 40, 30));
    float j[4];
    REQUIRE(pose.jacobian(j));
    CHECK(j[0] == Approx(std::cos(0.15)).margin(1e-5));
    CHECK(j[1] == Approx(-std::sin(0.15)).margin(1e-5));
    CHECK(j[2] == Approx(std::sin(0.15)).margin(1e-5));
    CHECK(j[3] == Approx(std::cos(0.15)).margin(1e-5));
    pose.reset(40.0f, 30.0f);
    REQUIRE(pose.jacobian(j));
    CHECK((j[0] == 1.0f && j[1] == 0.0f && j[2] == 0.0f && j[3] == 1.0f));
}

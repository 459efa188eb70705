// The float homography stage (core/target/float/homography.h) against independent double-precision
// references written here: an unnormalised 8×8 DLT (h9 = 1) solved by Gauss-Jordan, 3×3
// products and inverses in double, the exact minimiser of equation (7) by Gauss-Newton, the
// iteration-count formula with std::log; and RANSAC on generated inter-frame correspondences
// with a known H, gross outliers and Gaussian noise.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "base/prng.h"
#include "scene/plane_motion.h"
#include "scene/random.h"
#include "target/float/homography.h"

using namespace qt;

namespace {

using H64 = scene::Homography64;
using P = scene::Point64;
using scene::apply64;
using scene::mul64;

constexpr double kW = 320, kH = 240;  // the frame, px
const P kCorners[4] = {{0, 0}, {kW, 0}, {kW, kH}, {0, kH}};

H64 to64(const Homography& h) {
    H64 d;
    for (int i = 0; i < 9; ++i) d[i] = h.m[i];
    return d;
}

Homography to32(const H64& d) {
    Homography h;
    for (int i = 0; i < 9; ++i) h.m[i] = static_cast<float>(d[i]);
    return h;
}

// Reference DLT: the 8×8 system with h9 = 1 in pixel coordinates (no normalisation), solved by
// Gauss-Jordan with partial pivoting in double.
H64 dlt64(const P a[4], const P b[4]) {
    double m[8][9] = {};
    for (int i = 0; i < 4; ++i) {
        const double x = a[i].x, y = a[i].y, u = b[i].x, v = b[i].y;
        const double r1[9] = {x, y, 1, 0, 0, 0, -x * u, -y * u, u};
        const double r2[9] = {0, 0, 0, x, y, 1, -x * v, -y * v, v};
        for (int k = 0; k < 9; ++k) {
            m[2 * i][k] = r1[k];
            m[2 * i + 1][k] = r2[k];
        }
    }
    for (int c = 0; c < 8; ++c) {
        int piv = c;
        for (int r = c + 1; r < 8; ++r)
            if (std::fabs(m[r][c]) > std::fabs(m[piv][c])) piv = r;
        for (int k = 0; k < 9; ++k) std::swap(m[c][k], m[piv][k]);
        for (int r = 0; r < 8; ++r) {
            if (r == c) continue;
            const double f = m[r][c] / m[c][c];
            for (int k = c; k < 9; ++k) m[r][k] -= f * m[c][k];
        }
    }
    H64 h{};
    for (int i = 0; i < 8; ++i) h[i] = m[i][8] / m[i][i];
    h[8] = 1;
    return h;
}

// The exact term of equation (7): min over x̂ of |a − x̂|² + |b − H x̂|², by Gauss-Newton in
// double from x̂ = a (converges in a few steps for small errors).
double geometric_error_sq(const H64& h, P a, P b) {
    double x = a.x, y = a.y;
    for (int it = 0; it < 50; ++it) {
        const double w = h[6] * x + h[7] * y + h[8];
        const double u = (h[0] * x + h[1] * y + h[2]) / w, v = (h[3] * x + h[4] * y + h[5]) / w;
        // residual r = [x − ax, y − ay, u − bx, v − by], Jacobian J (4×2)
        const double r[4] = {x - a.x, y - a.y, u - b.x, v - b.y};
        const double j[4][2] = {{1, 0},
                                {0, 1},
                                {(h[0] - u * h[6]) / w, (h[1] - u * h[7]) / w},
                                {(h[3] - v * h[6]) / w, (h[4] - v * h[7]) / w}};
        double jtj[2][2] = {}, jtr[2] = {};
        for (int k = 0; k < 4; ++k) {
            for (int p = 0; p < 2; ++p) {
                jtr[p] += j[k][p] * r[k];
                for (int q = 0; q < 2; ++q) jtj[p][q] += j[k][p] * j[k][q];
            }
        }
        const double det = jtj[0][0] * jtj[1][1] - jtj[0][1] * jtj[1][0];
        const double dx = (jtj[1][1] * jtr[0] - jtj[0][1] * jtr[1]) / det;
        const double dy = (jtj[0][0] * jtr[1] - jtj[1][0] * jtr[0]) / det;
        x -= dx;
        y -= dy;
        if (std::fabs(dx) + std::fabs(dy) < 1e-14) break;
    }
    const P hx = apply64(h, x, y);
    return (x - a.x) * (x - a.x) + (y - a.y) * (y - a.y) + (hx.x - b.x) * (hx.x - b.x) +
           (hx.y - b.y) * (hx.y - b.y);
}

H64 random_motion(Pcg32& rng) { return scene::random_inter_frame_motion(rng, kW, kH); }

struct Scenario {
    H64 truth;
    std::vector<PointPair> pairs;
    std::vector<uint8_t> is_inlier;
};

// n pairs in the 320×240 frame; a fraction `outliers` of them have B uniform in the frame at
// least 6 px from the truth; the others get Gaussian noise of sigma px per coordinate, redrawn
// while the displacement exceeds `max_noise` px (so that the 2 px test separates the classes
// exactly and the expected inlier set is known).
Scenario make_scenario(uint64_t seed, int n, double outliers, double sigma, double max_noise) {
    Pcg32 rng(seed);
    scene::Gaussian gauss(Pcg32(seed, 77));
    Scenario s;
    s.truth = random_motion(rng);
    const int n_out = static_cast<int>(std::lround(outliers * n));
    for (int i = 0; i < n; ++i) {
        const double ax = scene::uniform(rng, 0, kW), ay = scene::uniform(rng, 0, kH);
        const P b = apply64(s.truth, ax, ay);
        double bx, by;
        if (i < n_out) {
            do {
                bx = scene::uniform(rng, 0, kW);
                by = scene::uniform(rng, 0, kH);
            } while (std::hypot(bx - b.x, by - b.y) < 6);
        } else {
            double nx, ny;
            do {
                nx = sigma * gauss.next();
                ny = sigma * gauss.next();
            } while (std::hypot(nx, ny) > max_noise);
            bx = b.x + nx;
            by = b.y + ny;
        }
        s.pairs.push_back({static_cast<float>(ax), static_cast<float>(ay), static_cast<float>(bx),
                           static_cast<float>(by)});
        s.is_inlier.push_back(i < n_out ? 0 : 1);
    }
    // Shuffle so that outliers are not a prefix (Fisher-Yates with the same generator).
    for (int i = n - 1; i > 0; --i) {
        const int j = static_cast<int>(rng.below(static_cast<uint32_t>(i + 1)));
        std::swap(s.pairs[i], s.pairs[j]);
        std::swap(s.is_inlier[i], s.is_inlier[j]);
    }
    return s;
}

// Mean and worst distance between the frame corners mapped by h and by the truth, px.
std::pair<double, double> corner_error(const Homography& h, const H64& truth) {
    double sum = 0, worst = 0;
    for (const P& c : kCorners) {
        const P e = apply64(to64(h), c.x, c.y), t = apply64(truth, c.x, c.y);
        const double d = std::hypot(e.x - t.x, e.y - t.y);
        sum += d;
        worst = std::max(worst, d);
    }
    return {sum / 4, worst};
}

}  // namespace

TEST_CASE("homography_from_4: a hand-worked scale and shift is exact", "[homography]") {
    // Unit square → x' = 2x + 10, y' = 3y + 20: H = [2 0 10; 0 3 20; 0 0 1].
    const PointPair pairs[4] = {{0, 0, 10, 20}, {1, 0, 12, 20}, {1, 1, 12, 23}, {0, 1, 10, 23}};
    Homography h;
    REQUIRE(homography_from_4(pairs, h));
    const float want[9] = {2, 0, 10, 0, 3, 20, 0, 0, 1};
    for (int i = 0; i < 9; ++i) CHECK(h.m[i] == Approx(want[i]).margin(1e-5));
    CHECK(h.m[8] == 1.0f);
}

TEST_CASE("homography_from_4 recovers a known perspective H to float precision", "[homography]") {
    const H64 truth = {1.02, 0.05, 5, -0.03, 0.98, -3, 2e-4, -1e-4, 1};
    const P a[4] = {{12, 20}, {300, 8}, {290, 230}, {25, 215}};
    P b[4];
    PointPair pairs[4];
    for (int i = 0; i < 4; ++i) {
        b[i] = apply64(truth, a[i].x, a[i].y);
        pairs[i] = {static_cast<float>(a[i].x), static_cast<float>(a[i].y),
                    static_cast<float>(b[i].x), static_cast<float>(b[i].y)};
    }
    // The reference DLT reproduces the truth (checks the reference itself).
    const H64 ref = dlt64(a, b);
    for (int i = 0; i < 9; ++i) REQUIRE(ref[i] == Approx(truth[i]).margin(1e-12));
    Homography h;
    REQUIRE(homography_from_4(pairs, h));
    CHECK(h.m[8] == 1.0f);
    const auto err = corner_error(h, truth);
    CHECK(err.second < 1e-3);
    for (int i = 0; i < 4; ++i) {  // the four pairs themselves
        float x = 0, y = 0;
        REQUIRE(apply_homography(h, pairs[i].ax, pairs[i].ay, x, y));
        CHECK(std::hypot(x - b[i].x, y - b[i].y) < 1e-3);
    }
    // Many random plausible motions and random samples against the double reference.
    Pcg32 rng(2024);
    double worst = 0;
    int solved = 0;
    for (int t = 0; t < 500; ++t) {
        const H64 m = random_motion(rng);
        P aa[4], bb[4];
        PointPair pp[4];
        for (int i = 0; i < 4; ++i) {
            aa[i] = {scene::uniform(rng, 0, kW), scene::uniform(rng, 0, kH)};
            // Float inputs: the reference sees the same rounded coordinates.
            aa[i] = {static_cast<float>(aa[i].x), static_cast<float>(aa[i].y)};
            const P q = apply64(m, aa[i].x, aa[i].y);
            bb[i] = {static_cast<float>(q.x), static_cast<float>(q.y)};
            pp[i] = {static_cast<float>(aa[i].x), static_cast<float>(aa[i].y),
                     static_cast<float>(bb[i].x), static_cast<float>(bb[i].y)};
        }
        Homography hh;
        if (!homography_from_4(pp, hh)) continue;  // a collinear triple: refused (tested below)
        ++solved;
        // Compared where the four points are (a 4-point H extrapolates badly elsewhere).
        const H64 r = dlt64(aa, bb);
        for (int i = 0; i < 4; ++i) {
            const P e = apply64(to64(hh), aa[i].x, aa[i].y), q = apply64(r, aa[i].x, aa[i].y);
            worst = std::max(worst, std::hypot(e.x - q.x, e.y - q.y));
        }
    }
    CHECK(solved > 400);
    CHECK(worst < 2e-3);
}

TEST_CASE("nearly_collinear: order-independent smallest-angle test", "[homography]") {
    CHECK(nearly_collinear(0, 0, 10, 10, 20, 20, 0.01f));     // exactly on a line
    CHECK(nearly_collinear(0, 0, 0, 0, 5, 7, 0.01f));         // two coincident points
    CHECK(nearly_collinear(3, 3, 3, 3, 3, 3, 0.01f));         // all coincident
    CHECK_FALSE(nearly_collinear(0, 0, 10, 0, 0, 10, 0.5f));  // right isosceles: sin 45° = 0.71
    CHECK(nearly_collinear(0, 0, 10, 0, 0, 10, 0.75f));
    // A thin triangle: smallest angle atan(1/100) = 0.573°, sin = 0.0100. Every order gives the
    // same answer (the angle at (0, 0) is 90°).
    const float x[3] = {0, 100, 0}, y[3] = {0, 0, 1};
    const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& p : perm) {
        CHECK(nearly_collinear(x[p[0]], y[p[0]], x[p[1]], y[p[1]], x[p[2]], y[p[2]], 0.0101f));
        CHECK_FALSE(
            nearly_collinear(x[p[0]], y[p[0]], x[p[1]], y[p[1]], x[p[2]], y[p[2]], 0.0099f));
    }
    CHECK(nearly_collinear(0, 0, NAN, 0, 0, 10, 0.01f));  // NaN counts as collinear
}

TEST_CASE("homography_from_4 refuses collinear samples in either image", "[homography]") {
    const PointPair good[4] = {{0, 0, 1, 2}, {100, 0, 101, 1}, {100, 80, 102, 83}, {0, 80, 0, 81}};
    Homography h;
    REQUIRE(homography_from_4(good, h));
    // Three A points on a line.
    PointPair bad[4] = {{0, 0, 1, 2}, {50, 0, 51, 1}, {100, 0, 102, 3}, {0, 80, 0, 81}};
    CHECK_FALSE(homography_from_4(bad, h));
    // Three B points on a line (A in general position).
    PointPair bad_b[4] = {{0, 0, 0, 0}, {100, 0, 50, 50}, {100, 80, 100, 100}, {0, 80, 0, 81}};
    CHECK_FALSE(homography_from_4(bad_b, h));
    // Nearly collinear: the third point 0.5 px off a 100 px line (sin 0.01 < 0.02).
    PointPair thin[4] = {{0, 0, 1, 2}, {50, 0.5f, 51, 2}, {100, 0, 101, 2}, {0, 80, 0, 81}};
    CHECK_FALSE(homography_from_4(thin, h));
    // Coincident points.
    PointPair same[4] = {{10, 10, 10, 10}, {10, 10, 10, 10}, {100, 80, 102, 83}, {0, 80, 0, 81}};
    CHECK_FALSE(homography_from_4(same, h));
    // The output is untouched on refusal.
    Homography untouched;
    untouched.m[2] = 42;
    CHECK_FALSE(homography_from_4(bad, untouched));
    CHECK(untouched.m[2] == 42.0f);
}

TEST_CASE("apply, multiply and invert agree with double math, and H⁻¹·H = I", "[homography]") {
    Pcg32 rng(7);
    for (int t = 0; t < 200; ++t) {
        H64 a = random_motion(rng), b = random_motion(rng);
        if (t % 2) {  // stronger perspective on every other case
            a[6] *= 20;
            b[7] *= 20;
        }
        const Homography fa = to32(a), fb = to32(b);
        const H64 a32 = to64(fa), b32 = to64(fb);  // the float entries, exactly
        for (int k = 0; k < 4; ++k) {
            const float x = static_cast<float>(scene::uniform(rng, 0, kW));
            const float y = static_cast<float>(scene::uniform(rng, 0, kH));
            float u = 0, v = 0;
            REQUIRE(apply_homography(fa, x, y, u, v));
            const P r = apply64(a32, x, y);
            CHECK(std::fabs(u - r.x) < 1e-4);
            CHECK(std::fabs(v - r.y) < 1e-4);
        }
        Homography ab;
        REQUIRE(multiply_homographies(fa, fb, ab));
        CHECK(ab.m[8] == 1.0f);
        const H64 rab = scene::normalised64(mul64(a32, b32));
        for (int i = 0; i < 9; ++i)
            CHECK(ab.m[i] == Approx(rab[i]).margin(1e-6 * (i == 2 || i == 5 ? 100 : 1)));
        Homography inv;
        REQUIRE(invert_homography(fa, inv));
        CHECK(inv.m[8] == 1.0f);
        Homography id;
        REQUIRE(multiply_homographies(inv, fa, id));
        const float eye[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        for (int i = 0; i < 9; ++i)
            CHECK(id.m[i] ==
                  Approx(eye[i]).margin(i == 2 || i == 5 ? 1e-4 : (i >= 6 ? 1e-9 : 1e-6)));
        // The inverse maps the frame corners back within 1e-3 px.
        for (const P& c : kCorners) {
            float u = 0, v = 0, x = 0, y = 0;
            REQUIRE(apply_homography(fa, static_cast<float>(c.x), static_cast<float>(c.y), u, v));
            REQUIRE(apply_homography(inv, u, v, x, y));
            CHECK(std::hypot(x - c.x, y - c.y) < 1e-3);
        }
    }
}

TEST_CASE("apply/multiply/invert refuse points at infinity and singular matrices", "[homography]") {
    Homography h;
    h.m[6] = 0.01f;  // w' = 0.01 x + 1: the horizon is the line x = −100
    float u = 7, v = 7;
    CHECK(apply_homography(h, 10, 5, u, v));
    CHECK_FALSE(apply_homography(h, -100, 5, u, v));
    CHECK_FALSE(apply_homography(h, -300, 5, u, v));  // behind the horizon
    CHECK_FALSE(apply_homography(h, NAN, 5, u, v));
    CHECK(transfer_error_sq(h, {-100, 5, 0, 0}) == FLT_MAX);
    CHECK(reprojection_error_sq(h, {-100, 5, 0, 0}) == FLT_MAX);
    Homography singular;  // rank 2: third row = first + second
    const float s[9] = {1, 2, 3, 4, 5, 6, 5, 7, 9};
    std::memcpy(singular.m, s, sizeof s);
    Homography out;
    out.m[0] = 42;
    CHECK_FALSE(invert_homography(singular, out));
    CHECK(out.m[0] == 42.0f);
    // A product whose m[8] is 0: a's third row is (−1, 0, 1) and b maps the origin to (1, 0, 1),
    // so a·b maps the origin to w' = −1 + 1 = 0.
    Homography a, b;
    a.m[6] = -1;
    b.m[2] = 1;
    CHECK_FALSE(multiply_homographies(a, b, out));
    CHECK(out.m[0] == 42.0f);
}

TEST_CASE("Sampson error: zero for exact pairs, the exact equation (7) term for small errors",
          "[homography]") {
    // A strong perspective, so that first-order and exact differ measurably.
    const H64 truth = {1.05, 0.08, 12, -0.06, 0.97, -7, 8e-4, -5e-4, 1};
    const Homography h = to32(truth);
    const H64 h32 = to64(h);
    Pcg32 rng(99);
    scene::Gaussian gauss(Pcg32(99, 5));
    double worst_rel = 0, worst_exact = 0;
    for (int i = 0; i < 300; ++i) {
        const double ax = scene::uniform(rng, 0, kW), ay = scene::uniform(rng, 0, kH);
        const P b = apply64(h32, ax, ay);
        const PointPair exact = {static_cast<float>(ax), static_cast<float>(ay),
                                 static_cast<float>(b.x), static_cast<float>(b.y)};
        worst_exact = std::max(worst_exact, static_cast<double>(reprojection_error_sq(h, exact)));
        // Errors of 0.1-2 px on both sides.
        const double sc = scene::uniform(rng, 0.1, 1.0);
        const PointPair p = {static_cast<float>(ax + sc * gauss.next()),
                             static_cast<float>(ay + sc * gauss.next()),
                             static_cast<float>(b.x + sc * gauss.next()),
                             static_cast<float>(b.y + sc * gauss.next())};
        const double ref = geometric_error_sq(h32, {p.ax, p.ay}, {p.bx, p.by});
        const double got = reprojection_error_sq(h, p);
        if (ref > 1e-4) worst_rel = std::max(worst_rel, std::fabs(got - ref) / ref);
        CHECK(std::fabs(got - ref) <= 2e-3 * ref + 1e-6);
    }
    CHECK(worst_exact < 1e-8);  // px²: float rounding of the exact pairs only
    INFO("worst relative difference " << worst_rel);
    CHECK(worst_rel < 2e-3);
    // Affine H: the algebraic residual is linear in the coordinates, so Sampson is exact.
    const H64 aff = {1.1, 0.2, 3, -0.1, 0.9, 4, 0, 0, 1};
    const PointPair q = {100, 50, 125, 40};
    CHECK(reprojection_error_sq(to32(aff), q) ==
          Approx(geometric_error_sq(aff, {100, 50}, {125, 40})).epsilon(1e-5));
    // For H = I the geometric error splits the displacement between the two images: d²/2.
    CHECK(reprojection_error_sq(Homography{}, {10, 10, 13, 14}) == Approx(12.5).epsilon(1e-6));
    CHECK(transfer_error_sq(Homography{}, {10, 10, 13, 14}) == Approx(25).epsilon(1e-6));
}

TEST_CASE("iteration count: N = ceil(log(1-c)/log(1-w^4)) as in double", "[homography]") {
    int compared = 0;
    for (uint32_t n : {8u, 50u, 200u, 1000u, 65535u}) {
        for (uint32_t k = 1; k <= n; k += (n > 300 ? n / 97 : 1)) {
            for (float c : {0.9f, 0.99f, 0.995f, 0.999f}) {
                const double w = static_cast<double>(k) / n;
                const double p = std::pow(w, 4);
                const uint16_t got = ransac_iterations_needed(k, n, c, 60000);
                if (k == n) {
                    CHECK(got == 0);
                    continue;
                }
                const double nf = std::log(1.0 - static_cast<double>(c)) / std::log1p(-p);
                if (nf >= 60000) {
                    CHECK(got == 60000);
                    continue;
                }
                // Skip cases within 1e-3 of an integer (and very small p, where 1 − p in float
                // loses relative precision): the float formula may round either way there.
                if (std::fabs(nf - std::round(nf)) < 1e-3 * std::max(1.0, nf) || p < 1e-4) continue;
                CHECK(got == static_cast<uint16_t>(std::ceil(nf)));
                ++compared;
            }
        }
    }
    CHECK(compared > 1000);
    CHECK(ransac_iterations_needed(0, 100, 0.995f, 1000) == 1000);
    CHECK(ransac_iterations_needed(50, 100, 1.0f, 1000) == 1000);  // c >= 1: never adapt
    CHECK(ransac_iterations_needed(50, 100, NAN, 1000) == 1000);
    CHECK(ransac_iterations_needed(50, 100, 0.0f, 1000) == 0);
    // w = 0.5, c = 0.995: log(0.005)/log(1 − 1/16) = 82.1 → 83.
    CHECK(ransac_iterations_needed(100, 200, 0.995f, 1000) == 83);
}

TEST_CASE("refit_homography: exact on exact data, refuses collinear or too few", "[homography]") {
    Pcg32 rng(11);
    const H64 truth = random_motion(rng);
    std::vector<PointPair> pairs;
    for (int i = 0; i < 30; ++i) {
        const double x = scene::uniform(rng, 0, kW), y = scene::uniform(rng, 0, kH);
        const P b = apply64(truth, x, y);
        pairs.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(b.x),
                         static_cast<float>(b.y)});
    }
    Homography h;
    REQUIRE(refit_homography(pairs.data(), 30, nullptr, h));
    CHECK(h.m[8] == 1.0f);
    CHECK(corner_error(h, truth).second < 1e-3);
    // A mask of 4 selects exactly those.
    std::vector<uint8_t> mask(30, 0);
    mask[3] = mask[8] = mask[17] = mask[25] = 1;
    REQUIRE(refit_homography(pairs.data(), 30, mask.data(), h));
    for (int i : {3, 8, 17, 25}) {  // the four points are fitted exactly (to float precision)
        float u = 0, v = 0;
        REQUIRE(apply_homography(h, pairs[i].ax, pairs[i].ay, u, v));
        CHECK(std::hypot(u - pairs[i].bx, v - pairs[i].by) < 1e-3);
    }
    mask[25] = 0;
    CHECK_FALSE(refit_homography(pairs.data(), 30, mask.data(), h));
    // All on one line: the null space is two-dimensional.
    std::vector<PointPair> line;
    for (int i = 0; i < 20; ++i)
        line.push_back({10.0f + 10 * i, 20.0f + 5 * i, 12.0f + 10 * i, 21.0f + 5 * i});
    CHECK_FALSE(refit_homography(line.data(), 20, nullptr, h));
}

TEST_CASE("RANSAC recovers a known inter-frame H through noise and 0/25/50 % outliers",
          "[homography]") {
    RansacParams cfg;  // 2 px, c = 0.995, 1000 iterations
    for (double frac : {0.0, 0.25, 0.5}) {
        double sum_mean = 0, worst = 0, sum_rep = 0;
        int max_it = 0;
        const int trials = 40;
        for (int t = 0; t < trials; ++t) {
            const Scenario s = make_scenario(1000 + t, 200, frac, 0.5, 1.5);
            std::vector<uint8_t> mask(200, 7);
            cfg.seed = 5 + t;
            const RansacResult r = estimate_homography(s.pairs.data(), 200, cfg, mask.data());
            REQUIRE(r.status == HomographyStatus::ok);
            CHECK(r.h.m[8] == 1.0f);
            CHECK(mask == s.is_inlier);  // exactly the inliers
            CHECK(r.inliers == std::count(s.is_inlier.begin(), s.is_inlier.end(), 1));
            const auto e = corner_error(r.h, s.truth);
            sum_mean += e.first;
            worst = std::max(worst, e.second);
            sum_rep += r.reprojection_px;
            max_it = std::max(max_it, static_cast<int>(r.iterations));
        }
        const double mean = sum_mean / trials;
        INFO("outliers " << frac << ": mean corner error " << mean << " px, worst " << worst
                         << " px, mean reprojection " << sum_rep / trials << " px, max iterations "
                         << max_it);
        CHECK(mean <= 0.3);
        CHECK(worst <= 1.0);
        // Noise 0.5 px per coordinate on B only: Sampson ≈ |noise|²/2, mean σ² → 0.5 px (a little
        // less: the noise is truncated at 1.5 px and the fit absorbs 8 degrees of freedom).
        CHECK(sum_rep / trials > 0.4);
        CHECK(sum_rep / trials < 0.55);
        if (frac == 0.0) CHECK(max_it <= 20);  // adaptive: far fewer than 1000
        if (frac == 0.5) CHECK(max_it < 1000);
    }
}

TEST_CASE("RANSAC is deterministic: same pairs and seed, same bits", "[homography]") {
    const Scenario s = make_scenario(4242, 200, 0.4, 0.5, 10);
    RansacParams cfg;
    cfg.seed = 123;
    std::vector<uint8_t> m1(200), m2(200);
    const RansacResult a = estimate_homography(s.pairs.data(), 200, cfg, m1.data());
    const RansacResult b = estimate_homography(s.pairs.data(), 200, cfg, m2.data());
    REQUIRE(a.status == HomographyStatus::ok);
    CHECK(std::memcmp(a.h.m, b.h.m, sizeof a.h.m) == 0);
    CHECK(a.iterations == b.iterations);
    CHECK(a.inliers == b.inliers);
    CHECK(std::memcmp(&a.reprojection_px, &b.reprojection_px, sizeof(float)) == 0);
    CHECK(m1 == m2);
    // Without a mask the result is the same.
    const RansacResult c = estimate_homography(s.pairs.data(), 200, cfg, nullptr);
    CHECK(std::memcmp(a.h.m, c.h.m, sizeof a.h.m) == 0);
    // Another seed draws other samples (at 40 % outliers the count differs or the bits do).
    cfg.seed = 124;
    const RansacResult d = estimate_homography(s.pairs.data(), 200, cfg, nullptr);
    REQUIRE(d.status == HomographyStatus::ok);
    CHECK(corner_error(d.h, s.truth).second < 1.0);
}

TEST_CASE("RANSAC statuses: too few pairs, degenerate, no consensus", "[homography]") {
    RansacParams cfg;
    const Scenario s = make_scenario(77, 60, 0.0, 0.5, 1.5);
    std::vector<uint8_t> mask(60, 9);
    RansacResult r = estimate_homography(s.pairs.data(), 3, cfg, mask.data());
    CHECK(r.status == HomographyStatus::too_few_pairs);
    CHECK(mask[0] == 0);
    CHECK(estimate_homography(nullptr, 0, cfg, nullptr).status == HomographyStatus::too_few_pairs);
    cfg.min_inliers = 20;
    CHECK(estimate_homography(s.pairs.data(), 10, cfg, nullptr).status ==
          HomographyStatus::too_few_pairs);
    // Every point on one line: every sample has a collinear triple.
    std::vector<PointPair> line;
    for (int i = 0; i < 40; ++i)
        line.push_back({5.0f + 7 * i, 3.0f + 5 * i, 6.0f + 7 * i, 2.0f + 5 * i});
    cfg = RansacParams{};
    cfg.max_iterations = 300;
    r = estimate_homography(line.data(), 40, cfg, nullptr);
    CHECK(r.status == HomographyStatus::degenerate);
    CHECK(r.iterations == 300);
    CHECK(r.h.m[0] == 1.0f);
    CHECK(r.h.m[2] == 0.0f);
    // Unrelated pairs: a 4-point H explains its own 4 and a few by chance, not 20.
    Pcg32 rng(5);
    std::vector<PointPair> junk;
    for (int i = 0; i < 100; ++i)
        junk.push_back({static_cast<float>(scene::uniform(rng, 0, kW)),
                        static_cast<float>(scene::uniform(rng, 0, kH)),
                        static_cast<float>(scene::uniform(rng, 0, kW)),
                        static_cast<float>(scene::uniform(rng, 0, kH))});
    cfg = RansacParams{};
    cfg.min_inliers = 20;
    std::vector<uint8_t> jm(100, 9);
    r = estimate_homography(junk.data(), 100, cfg, jm.data());
    CHECK(r.status == HomographyStatus::no_consensus);
    CHECK(r.inliers >= 4);
    CHECK(r.inliers < 20);
    CHECK(r.iterations == 1000);  // w = r.inliers/100 never bounds N below 1000
    CHECK(std::count(jm.begin(), jm.end(), 0) == 100);
    CHECK(std::string(homography_status_name(HomographyStatus::no_consensus)).find("consensus") !=
          std::string::npos);
}

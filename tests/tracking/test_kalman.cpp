// The fixed-point Kalman filter of the 3KF tracker (core/tracking/kalman.h) against an independent
// double-precision reference: the paper's 4-state filter (the Quadrangle Detection paper §2.6, eqs.
// (3)–(5)) with full 4×4 matrices, X = A X, P = A P Aᵀ + Q, S = H P Hᵀ + R, K = P Hᵀ S⁻¹, X += K (Z
// − H X), P = (I − K H) P — no 2×2 shortcut, no block structure assumed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "base/prng.h"
#include "support/matrix_reference.h"
#include "tracking/kalman.h"

using namespace qt;

namespace {

constexpr double kQ16 = 65536.0;
constexpr double kCov = 4294967296.0;  // 2^32: covariance raw per px²
// A gain's real value from its raw value and fraction bits.
double gain(int64_t raw, int frac) { return std::ldexp(static_cast<double>(raw), -frac); }

double val(q16_16 v) { return v.raw / kQ16; }
q16_16 q16(double v) { return q16_16::from_raw(std::llround(v * kQ16)); }

// ---- the reference: 4×4, straight from equations (3)–(5) ---------------------------------------
using test::Mat;

struct RefKalman4 {
    Mat<4, 1> X;
    Mat<4, 4> P, A, Q, I;
    Mat<2, 4> H;
    Mat<2, 2> Rm;

    RefKalman4(double x, double y, double r, double q, double p0_pos, double p0_vel) {
        const double dt = 1;
        X.m[0][0] = x;
        X.m[2][0] = y;
        for (int i = 0; i < 4; ++i) I.m[i][i] = A.m[i][i] = 1;
        A.m[0][1] = A.m[2][3] = dt;
        H.m[0][0] = H.m[1][2] = 1;
        const double q4[4][4] = {{dt * dt * dt * dt / 4, dt * dt * dt / 2, 0, 0},
                                 {dt * dt * dt / 2, dt * dt, 0, 0},
                                 {0, 0, dt * dt * dt * dt / 4, dt * dt * dt / 2},
                                 {0, 0, dt * dt * dt / 2, dt * dt}};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) Q.m[i][j] = q * q4[i][j];
        Rm.m[0][0] = Rm.m[1][1] = r;
        P.m[0][0] = P.m[2][2] = p0_pos;
        P.m[1][1] = P.m[3][3] = p0_vel;
    }
    void predict() {
        X = A * X;
        P = A * P * transpose(A) + Q;
    }
    void update(double zx, double zy) {
        Mat<2, 1> Z;
        Z.m[0][0] = zx;
        Z.m[1][0] = zy;
        const Mat<2, 2> S = H * P * transpose(H) + Rm;
        const double det = S.m[0][0] * S.m[1][1] - S.m[0][1] * S.m[1][0];
        Mat<2, 2> Si;
        Si.m[0][0] = S.m[1][1] / det;
        Si.m[1][1] = S.m[0][0] / det;
        Si.m[0][1] = -S.m[0][1] / det;
        Si.m[1][0] = -S.m[1][0] / det;
        const Mat<4, 2> K = P * transpose(H) * Si;
        X = X + K * (Z - H * X);
        P = (I - K * H) * P;
    }
};

// Standard normal from two PCG32 draws (Box–Muller).
double gauss(Pcg32& rng) {
    const double u1 = (rng.next() + 0.5) / 4294967296.0;
    const double u2 = (rng.next() + 0.5) / 4294967296.0;
    return std::sqrt(-2 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

// A smooth trajectory: the acceleration is a damped random walk pulled weakly towards the
// centre, so the point wanders over hundreds of pixels at a few px/frame.
struct Walker {
    double pos, vel = 0, acc = 0;
    explicit Walker(double p) : pos(p) {}
    void step(Pcg32& rng) {
        acc = 0.9 * acc + 0.02 * gauss(rng) - 2e-5 * pos - 2e-3 * vel;
        vel += acc;
        pos += vel;
    }
};

struct Errors {
    double pos = 0, vel = 0, cov_rel = 0;
    void add(const PointKalman& f, const RefKalman4& ref) {
        pos = std::max(
            {pos, std::fabs(val(f.x()) - ref.X.m[0][0]), std::fabs(val(f.y()) - ref.X.m[2][0])});
        vel = std::max(
            {vel, std::fabs(val(f.vx()) - ref.X.m[1][0]), std::fabs(val(f.vy()) - ref.X.m[3][0])});
        const KalmanAxis* ax[2] = {&f.axis_x(), &f.axis_y()};
        for (int k = 0; k < 2; ++k) {
            const int o = 2 * k;
            const double fix[3] = {ax[k]->pp / kCov, ax[k]->pv / kCov, ax[k]->vv / kCov};
            const double ref3[3] = {ref.P.m[o][o], ref.P.m[o][o + 1], ref.P.m[o + 1][o + 1]};
            for (int i = 0; i < 3; ++i)
                cov_rel = std::max(cov_rel, std::fabs(fix[i] - ref3[i]) / std::fabs(ref3[i]));
            // Asymmetry in the reference would mean its algebra went wrong somewhere.
            REQUIRE(std::fabs(ref.P.m[o][o + 1] - ref.P.m[o + 1][o]) <=
                    1e-9 * std::fabs(ref.P.m[o][o + 1]));
        }
    }
};

}  // namespace

// (d) One predict + update from init, worked by hand from the equations with the default
// parameters r = 1/2, q = 1, P0 = diag(1/2, 100), on both axes:
//   predict: a = 1/2 + 2·0 + 100 + 1/4 = 100.75 = 403/4,  b = 0 + 100 + 1/2 = 201/2,
//            c = 100 + 1 = 101;  S = a + r = 101.25 = 405/4
//   gain:    K₁ = a/S = 403/405 = 0.99506173,  K₂ = b/S = 402/405 = 134/135 = 0.99259259
//   update x: x0 = 10, z = 12, ν = 2:  x = 10 + 806/405 = 11.99012346,  ẋ = 804/405 = 1.98518519
//   update y: y0 = −20, z = −21, ν = −1: y = −20 − 403/405 = −20.99506173, ẏ = −402/405
//   P:  a = r·K₁ = 403/810 = 0.49753086,  b = r·K₂ = 67/135 = 0.49629630,
//       c = 101 − b·K₂ = 101 − (201/2)(134/135) = 56/45 = 1.24444444  (both axes)
TEST_CASE("Kalman: first predict and update equal the hand-worked values", "[kalman]") {
    PointKalman f;
    REQUIRE(f.init(q16_16::from_int(10), q16_16::from_int(-20)));
    f.predict();
    REQUIRE(f.axis_x().pp == 403 * (INT64_C(1) << 30));  // exact: 403/4 px² with 32 fraction bits
    REQUIRE(f.axis_x().pv == 201 * (INT64_C(1) << 31));
    REQUIRE(f.axis_x().vv == 101 * (INT64_C(1) << 32));
    // Gains: within one LSB of their formats (2^-59 and 2^-44). The exact raw values, from
    // integers: K₁ = 403·2^59/405, K₂ = 402·2^44/405, rounded.
    const KalmanGain g = f.gain_x();
    const int64_t k1 = static_cast<int64_t>((static_cast<__int128>(403) << 59) / 405);
    const int64_t k2 = static_cast<int64_t>((static_cast<__int128>(402) << 44) / 405);
    CHECK(std::llabs(g.k_pos - k1) <= 1);
    CHECK(std::llabs(g.k_vel - k2) <= 1);
    const KalmanGain gy = f.gain_y();
    CHECK(gy.k_pos == g.k_pos);
    CHECK(gy.k_vel == g.k_vel);

    f.update(q16_16::from_int(12), q16_16::from_int(-21));
    CHECK(std::llabs(f.x().raw - std::llround((10 + 806.0 / 405) * kQ16)) <= 1);
    CHECK(std::llabs(f.vx().raw - std::llround(804.0 / 405 * kQ16)) <= 1);
    CHECK(std::llabs(f.y().raw - std::llround((-20 - 403.0 / 405) * kQ16)) <= 1);
    CHECK(std::llabs(f.vy().raw - std::llround(-402.0 / 405 * kQ16)) <= 1);
    // The covariance: within one LSB of its 32 fraction bits.
    for (const KalmanAxis* ax : {&f.axis_x(), &f.axis_y()}) {
        CHECK(std::llabs(ax->pp - std::llround(403.0 / 810 * kCov)) <= 1);
        CHECK(std::llabs(ax->pv - std::llround(67.0 / 135 * kCov)) <= 1);
        CHECK(std::llabs(ax->vv - std::llround(56.0 / 45 * kCov)) <= 1);
    }
    CHECK(f.flags() == 0);
    INFO("sizeof(PointKalman) = " << sizeof(PointKalman) << " bytes");
    CHECK(sizeof(PointKalman) == 80);
}

// (a) 10,000 frames of a noisy trajectory, side by side with the 4×4 reference.
TEST_CASE("Kalman: 10000 noisy frames track the double 4-state reference", "[kalman]") {
    Pcg32 rng(2024);
    Walker wx(150), wy(-80);
    const double sigma = 0.7;  // measurement noise, px
    const q16_16 zx0 = q16(wx.pos + sigma * gauss(rng)), zy0 = q16(wy.pos + sigma * gauss(rng));
    PointKalman f;
    f.init(zx0, zy0);
    RefKalman4 ref(val(zx0), val(zy0), 0.5, 1, 0.5, 100);
    Errors err;
    double lo = 1e9, hi = -1e9, vmax = 0;
    for (int t = 1; t <= 10000; ++t) {
        wx.step(rng);
        wy.step(rng);
        lo = std::min({lo, wx.pos, wy.pos});
        hi = std::max({hi, wx.pos, wy.pos});
        vmax = std::max({vmax, std::fabs(wx.vel), std::fabs(wy.vel)});
        // Both filters see the same measurement: the q16_16 value, exactly.
        const q16_16 zx = q16(wx.pos + sigma * gauss(rng)), zy = q16(wy.pos + sigma * gauss(rng));
        f.predict();
        ref.predict();
        f.update(zx, zy);
        ref.update(val(zx), val(zy));
        err.add(f, ref);
    }
    INFO("trajectory spans [" << lo << ", " << hi << "] px, speed up to " << vmax << " px/frame");
    INFO("worst |x - ref| = " << err.pos << " px, |v - ref| = " << err.vel
                              << " px/frame, covariance relative " << err.cov_rel);
    REQUIRE(hi - lo > 300);  // the point did wander over hundreds of pixels
    REQUIRE(err.pos <= 0.05);
    REQUIRE(err.vel <= 0.01);
    REQUIRE(err.cov_rel <= 1e-6);
    REQUIRE(f.flags() == 0);
}

// (b) 100 frames without a measurement in the middle of a run, then updates resume.
TEST_CASE("Kalman: a 100-frame spell of prediction agrees with the reference", "[kalman]") {
    Pcg32 rng(99);
    Walker wx(-300), wy(420);
    const q16_16 zx0 = q16(wx.pos), zy0 = q16(wy.pos);
    PointKalman f;
    f.init(zx0, zy0);
    RefKalman4 ref(val(zx0), val(zy0), 0.5, 1, 0.5, 100);
    Errors err, err_coast;
    for (int t = 1; t <= 500; ++t) {
        wx.step(rng);
        wy.step(rng);
        const q16_16 zx = q16(wx.pos + 0.7 * gauss(rng)), zy = q16(wy.pos + 0.7 * gauss(rng));
        f.predict();
        ref.predict();
        const bool coasting = t > 200 && t <= 300;
        if (!coasting) {
            f.update(zx, zy);
            ref.update(val(zx), val(zy));
        }
        (coasting ? err_coast : err).add(f, ref);
        if (t == 300) {
            // After 100 predictions from the steady state: a ≈ n³/3 px², far below the ceiling.
            INFO("Ppp after the spell " << f.axis_x().pp / kCov << " px², reference "
                                        << ref.P.m[0][0]);
            REQUIRE(f.axis_x().pp / kCov > 3e5);
            REQUIRE(f.flags() == 0);
        }
        // The reference's cross-axis blocks stay exactly zero: the 2×2 split loses nothing.
        for (int i = 0; i < 2; ++i)
            for (int j = 2; j < 4; ++j) REQUIRE(ref.P.m[i][j] == 0);
    }
    INFO("updating: worst |x - ref| = " << err.pos << " px, |v - ref| = " << err.vel
                                        << " px/frame, covariance relative " << err.cov_rel);
    INFO("coasting: worst |x - ref| = " << err_coast.pos << " px, |v - ref| = " << err_coast.vel
                                        << " px/frame, covariance relative " << err_coast.cov_rel);
    REQUIRE(err.pos <= 0.05);
    REQUIRE(err_coast.pos <= 0.05);
    REQUIRE(err.vel <= 0.01);
    REQUIRE(err_coast.vel <= 0.01);
    REQUIRE(err.cov_rel <= 1e-6);
    REQUIRE(err_coast.cov_rel <= 1e-6);
}

// (c) A very long prediction-only run: the covariance and the state saturate, never wrap.
TEST_CASE("Kalman: long prediction saturates at the ceiling and flags it", "[kalman]") {
    const int64_t ceil = PointKalman::kCovCeiling;

    SECTION("the flag rises exactly when Ppp = 1/2 + 100 n² + n³/3 − n/12 passes 2^28 px²") {
        PointKalman f;
        f.init(q16_16::from_int(0), q16_16::from_int(0));
        int first = 0;
        for (int n = 1; n <= 2000 && first == 0; ++n) {
            f.predict();
            // 12·Ppp(n) in exact integers (prediction is exact in fixed point).
            const int64_t twelve_a =
                6 + 1200 * static_cast<int64_t>(n) * n + 4 * static_cast<int64_t>(n) * n * n - n;
            if (twelve_a <= 12 * (INT64_C(1) << 28)) {
                REQUIRE(f.flags() == 0);
                REQUIRE(static_cast<__int128>(f.axis_x().pp) * 12 == static_cast<__int128>(twelve_a)
                                                                         << 32);
            } else {
                first = n;
            }
        }
        INFO("first saturated frame " << first);
        REQUIRE(f.flags() == KalmanFlags::covariance_saturated);
        REQUIRE(first > 800);
        REQUIRE(first < 900);
        REQUIRE(f.axis_x().pp == ceil);
    }

    SECTION("10^5 frames with velocity: P at its bounds, position at the q16_16 limits") {
        PointKalman f;
        f.init(q16_16::from_int(100), q16_16::from_int(-100));
        f.predict();
        f.update(q16_16::from_int(103), q16_16::from_int(-103));  // about ±3 px/frame
        REQUIRE(f.vx() > q16_16::from_int(2));
        REQUIRE(f.vy() < q16_16::from_int(-2));
        const int64_t vv0 = f.axis_x().vv;
        KalmanAxis prev = f.axis_x();
        q16_16 prev_y = f.y();
        for (int n = 1; n <= 100000; ++n) {
            f.predict();
            const KalmanAxis& ax = f.axis_x();
            // Monotone, bounded, never wrapped; P stays positive semi-definite.
            REQUIRE(ax.pp >= prev.pp);
            REQUIRE(ax.pp <= ceil);
            REQUIRE(ax.vv == vv0 + n * (INT64_C(1) << 32));  // c = c0 + q·n, exact
            REQUIRE(ax.pv >= 0);
            REQUIRE(static_cast<__int128>(ax.pv) * ax.pv <= static_cast<__int128>(ax.pp) * ax.vv);
            REQUIRE(ax.pos >= prev.pos);
            REQUIRE(f.y() <= prev_y);
            REQUIRE(f.axis_y().pp == ax.pp);
            prev = ax;
            prev_y = f.y();
        }
        REQUIRE(f.flags() == (KalmanFlags::covariance_saturated | KalmanFlags::state_saturated));
        REQUIRE(f.axis_x().pp == ceil);
        REQUIRE(f.x().raw == INT32_MAX);
        REQUIRE(f.y().raw == INT32_MIN);
        // An update after saturation is still defined: the position jumps to the measurement.
        f.update(q16_16::from_int(50), q16_16::from_int(60));
        CHECK(std::fabs(val(f.x()) - 50) < 0.01);
        CHECK(std::fabs(val(f.y()) - 60) < 0.01);
        CHECK(f.axis_x().pp <= (INT64_C(1) << 31));  // <= r
        CHECK(f.saturated());                        // sticky until init()
        f.init(q16_16::from_int(1), q16_16::from_int(2));
        CHECK(f.flags() == 0);
    }

    SECTION("10^6 frames with q = 1024: every covariance term at the ceiling") {
        KalmanParams p;
        p.q = q16_16::from_int(1024);
        PointKalman f;
        REQUIRE(f.init(q16_16::from_int(0), q16_16::from_int(0), p));
        for (int n = 0; n < 1000000; ++n) f.predict();
        REQUIRE(f.flags() == KalmanFlags::covariance_saturated);  // velocity 0: the state stays put
        for (const KalmanAxis* ax : {&f.axis_x(), &f.axis_y()}) {
            REQUIRE(ax->pp == ceil);
            REQUIRE(ax->pv == ceil);  // ⌊√2^60⌋² = 2^60
            REQUIRE(ax->vv == ceil);
            REQUIRE(ax->pos.raw == 0);
        }
    }
}

TEST_CASE("Kalman: parameters outside their ranges are clamped and reported", "[kalman]") {
    PointKalman f;
    KalmanParams p;
    p.r = q16_16::from_int(0);  // R = 0 would make S = 0 possible
    REQUIRE_FALSE(f.init(q16_16::from_int(0), q16_16::from_int(0), p));
    f.predict();
    const KalmanGain g = f.gain_x();  // r clamped to 1/16: S = 100.75 + 1/16 > 0
    CHECK(std::fabs(gain(g.k_pos, KalmanGain::pos_frac) - 100.75 / 100.8125) <= std::ldexp(1, -30));
    p = KalmanParams{};
    p.p0_vel = q16_16::from_int(-5);
    REQUIRE_FALSE(f.init(q16_16::from_int(0), q16_16::from_int(0), p));
    CHECK(f.axis_x().vv == 0);
    REQUIRE(f.init(q16_16::from_int(0), q16_16::from_int(0), KalmanParams{}));
}

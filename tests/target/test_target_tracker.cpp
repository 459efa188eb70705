// The target tracker (the Filtering and Geometry paper §III, Tables II and III): its float Kalman
// filter (core/target/float/target_kalman.h) against an independent double-precision 4×4 filter
// written here from the textbook equations, change_frame() against exact scalings and a
// finite-difference Jacobian, the fused tracker's states, gates, reset and lost rules on
// hand-worked frames (core/target/float/target_tracker.h), the comparison methods, and
// match_displacement_q8 (core/target/float/frame_homography.h) on patches rendered from a smooth
// function at sub-pixel shifts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "base/prng.h"
#include "scene/random.h"
#include "support/matrix_reference.h"
#include "target/float/frame_homography.h"
#include "target/float/homography.h"
#include "target/float/target_kalman.h"
#include "target/float/target_tracker.h"

using namespace qt;

namespace {

// ---- the reference: full 4×4 matrices in double, X = Φ X, P = Φ P Φᵀ + Q, S = H P Hᵀ + R,
// K = P Hᵀ S⁻¹, X += K ν, P = (I − K H) P. No block structure assumed. ----------------------
using test::Mat;

struct RefKalman {
    Mat<4, 1> x;
    Mat<4, 4> p, phi, q;
    Mat<2, 4> h;
    Mat<2, 2> r;
    RefKalman(double x0, double y0, const TargetKalmanParams& k) {
        x.m[0][0] = x0;
        x.m[1][0] = y0;
        p.m[0][0] = p.m[1][1] = k.r;
        p.m[2][2] = p.m[3][3] = k.p0_vel;
        for (int i = 0; i < 4; ++i) phi.m[i][i] = 1;
        phi.m[0][2] = phi.m[1][3] = 1;  // Δt = 1 frame
        q.m[0][0] = q.m[1][1] = k.q_pos;
        q.m[2][2] = q.m[3][3] = k.q_vel;
        h.m[0][0] = h.m[1][1] = 1;
        r.m[0][0] = r.m[1][1] = k.r;
    }
    void predict() {
        x = phi * x;
        p = phi * p * transpose(phi) + q;
    }
    Mat<2, 2> s() const {
        Mat<2, 2> out = h * p * transpose(h);
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) out.m[i][j] += r.m[i][j];
        return out;
    }
    static double det(const Mat<2, 2>& a) { return a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0]; }
    static Mat<2, 2> inv(const Mat<2, 2>& a) {
        Mat<2, 2> out;
        const double d = det(a);
        out.m[0][0] = a.m[1][1] / d;
        out.m[1][1] = a.m[0][0] / d;
        out.m[0][1] = -a.m[0][1] / d;
        out.m[1][0] = -a.m[1][0] / d;
        return out;
    }
    Mat<2, 1> nu(double zx, double zy) const {
        Mat<2, 1> hx = h * x, out;
        out.m[0][0] = zx - hx.m[0][0];
        out.m[1][0] = zy - hx.m[1][0];
        return out;
    }
    double nds(double zx, double zy) const {
        const Mat<2, 1> v = nu(zx, zy);
        return (transpose(v) * inv(s()) * v).m[0][0];
    }
    void update(double zx, double zy) {
        const Mat<4, 2> k = p * transpose(h) * inv(s());
        const Mat<4, 1> dx = k * nu(zx, zy);
        for (int i = 0; i < 4; ++i) x.m[i][0] += dx.m[i][0];
        Mat<4, 4> ikh = k * h;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) ikh.m[i][j] = (i == j ? 1.0 : 0.0) - ikh.m[i][j];
        p = ikh * p;
    }
};

double kf_state(const TargetKalman& kf, int i) {
    return i == 0 ? kf.x() : i == 1 ? kf.y() : i == 2 ? kf.vx() : kf.vy();
}

// Worst relative deviation of the float filter from the reference: state entries relative to
// max(|ref|, 1) (px or px/frame), covariance entries relative to √(P_ii P_jj) (the entry's
// natural scale: a correlation of 1).
struct Deviation {
    double state = 0, cov = 0;
    void add(const TargetKalman& kf, const RefKalman& ref) {
        for (int i = 0; i < 4; ++i) {
            const double want = ref.x.m[i][0];
            state =
                std::max(state, std::abs(kf_state(kf, i) - want) / std::max(std::abs(want), 1.0));
            for (int j = 0; j < 4; ++j) {
                const double scale = std::sqrt(ref.p.m[i][i] * ref.p.m[j][j]);
                cov = std::max(cov, std::abs(kf.p(i, j) - ref.p.m[i][j]) / scale);
            }
        }
    }
};

// A stream of noisy measurements of a target with random accelerations, filtered by both.
void compare_with_reference(const TargetKalmanParams& params, uint64_t seed) {
    scene::Gaussian g{Pcg32(seed)};
    TargetKalman kf;
    kf.init(160.0f, 120.0f, params);
    RefKalman ref(160.0, 120.0, params);
    double tx = 160, ty = 120, vx = 1.5, vy = -0.7;
    Deviation dev;
    double worst_nds = 0, worst_det = 0, nds_sum = 0;
    dev.add(kf, ref);
    for (int k = 0; k < 200; ++k) {
        vx += 0.3 * g.next();
        vy += 0.3 * g.next();
        tx += vx;
        ty += vy;
        const float zx = static_cast<float>(tx + 2 * g.next()),
                    zy = static_cast<float>(ty + 2 * g.next());
        kf.predict();
        ref.predict();
        dev.add(kf, ref);
        const Innovation in = kf.innovation(zx, zy);
        const double want_nds = ref.nds(zx, zy), want_det = RefKalman::det(ref.s());
        worst_nds = std::max(worst_nds, std::abs(in.nds - want_nds) / std::max(want_nds, 1.0));
        worst_det = std::max(worst_det, std::abs(in.det_s - want_det) / want_det);
        nds_sum += want_nds;
        kf.update(in);
        ref.update(zx, zy);
        dev.add(kf, ref);
    }
    WARN("TargetKalman vs double: worst relative deviation: state "
         << dev.state << ", P " << dev.cov << ", NDS " << worst_nds << ", det S " << worst_det);
    CHECK(dev.state < 1e-4);
    CHECK(dev.cov < 1e-4);
    CHECK(worst_nds < 1e-4);
    CHECK(worst_det < 1e-4);
    // The measurements were not degenerate: the mean NDS is that of a χ² with 2 dof (~2), not 0.
    CHECK(nds_sum / 200 > 0.5);
}

Homography make_h(float h1, float h2, float h3, float h4, float h5, float h6, float h7, float h8) {
    Homography h;
    const float m[9] = {h1, h2, h3, h4, h5, h6, h7, h8, 1};
    for (int i = 0; i < 9; ++i) h.m[i] = m[i];
    return h;
}
Homography translation(float tx, float ty) { return make_h(1, 0, tx, 0, 1, ty, 0, 0); }
// Scaling by s about (cx, cy).
Homography scaling(float s, float cx, float cy) {
    return make_h(s, 0, cx * (1 - s), 0, s, cy * (1 - s), 0, 0);
}

FrameGeometry geometry(const Homography& h, float rep = 0.3f, bool valid = true) {
    FrameGeometry g;
    g.valid = valid;
    g.h = h;
    g.reprojection_px = g.d_rep_capped_px = rep;
    g.d_rep = rep * rep * 100;  // as if 100 pairs shared the error
    return g;
}
TargetMeasurement seen(float x, float y, float score = 0.9f) {
    TargetMeasurement m;
    m.found = true;
    m.x = x;
    m.y = y;
    m.score = score;
    return m;
}
const TargetMeasurement kNone{};

bool is_identity(const Homography& h) {
    const Homography id;
    for (int i = 0; i < 9; ++i)
        if (h.m[i] != id.m[i]) return false;
    return true;
}

// A filter with a non-zero velocity and a full covariance: a few noisy updates.
TargetKalman moving_filter() {
    TargetKalman kf;
    kf.init(100.0f, 80.0f, TargetKalmanParams{});
    const float zs[4][2] = {{103.1f, 78.2f}, {105.7f, 77.9f}, {109.2f, 75.1f}, {111.0f, 74.6f}};
    for (const auto& z : zs) {
        kf.predict();
        kf.update(kf.innovation(z[0], z[1]));
    }
    return kf;
}

}  // namespace

TEST_CASE("TargetKalman equals a double 4x4 Kalman filter over 200 noisy frames", "[target]") {
    SECTION("the paper's Q = diag(20, 20, 1, 1), R = 4 I") {
        compare_with_reference(TargetKalmanParams{}, 1);
    }
    SECTION("Q = diag(1, 1, 0.01, 0.01), R = 2 I, initial velocity variance 9") {
        TargetKalmanParams p;
        p.q_pos = 1;
        p.q_vel = 0.01f;
        p.r = 2;
        p.p0_vel = 9;
        compare_with_reference(p, 7);
    }
}

TEST_CASE("TargetKalman::change_frame: translation, scaling and a general homography", "[target]") {
    const TargetKalman before = moving_filter();
    REQUIRE(before.vx() > 1.0f);  // the velocity is not trivially zero
    REQUIRE(before.p(0, 2) != 0.0f);

    SECTION("a pure translation shifts the position exactly; velocity and P unchanged") {
        // J = I exactly ((1 − x'·0)/1), so T P Tᵀ sums only exact products by 1 and 0.
        TargetKalman kf = before;
        REQUIRE(kf.change_frame(translation(7.25f, -3.5f)));
        CHECK(kf.x() == before.x() + 7.25f);
        CHECK(kf.y() == before.y() - 3.5f);
        CHECK(kf.vx() == before.vx());
        CHECK(kf.vy() == before.vy());
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) CHECK(kf.p(i, j) == before.p(i, j));
    }
    SECTION("a scaling by s about the origin: position, velocity × s; every P block × s²") {
        for (const float s : {2.0f, 0.5f, 1.3f}) {
            TargetKalman kf = before;
            REQUIRE(kf.change_frame(scaling(s, 0, 0)));
            // J = s I; T = s I (4×4), so T P Tᵀ = s² P, every block alike.
            CHECK(kf.x() == Approx(before.x() * s).epsilon(1e-6));
            CHECK(kf.y() == Approx(before.y() * s).epsilon(1e-6));
            CHECK(kf.vx() == Approx(before.vx() * s).epsilon(1e-6));
            CHECK(kf.vy() == Approx(before.vy() * s).epsilon(1e-6));
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    CHECK(kf.p(i, j) == Approx(before.p(i, j) * s * s).epsilon(1e-6).margin(1e-9));
        }
    }
    SECTION("a general homography: apply_homography and a finite-difference Jacobian in double") {
        const Homography h = make_h(1.02f, 0.05f, 3.0f, -0.03f, 0.98f, -2.0f, 1e-4f, -2e-4f);
        TargetKalman kf = before;
        REQUIRE(kf.change_frame(h));
        float xo = 0, yo = 0;
        REQUIRE(apply_homography(h, before.x(), before.y(), xo, yo));
        CHECK(kf.x() == xo);
        CHECK(kf.y() == yo);
        // J by central differences of the double map, step 1e-3 px (truncation error ~1e-7).
        auto map = [&](double x, double y, double& u, double& v) {
            const double w = h.m[6] * x + h.m[7] * y + h.m[8];
            u = (h.m[0] * x + h.m[1] * y + h.m[2]) / w;
            v = (h.m[3] * x + h.m[4] * y + h.m[5]) / w;
        };
        const double x0 = before.x(), y0 = before.y(), d = 1e-3;
        double u1, v1, u2, v2, u3, v3, u4, v4;
        map(x0 + d, y0, u1, v1);
        map(x0 - d, y0, u2, v2);
        map(x0, y0 + d, u3, v3);
        map(x0, y0 - d, u4, v4);
        const double j[2][2] = {{(u1 - u2) / (2 * d), (u3 - u4) / (2 * d)},
                                {(v1 - v2) / (2 * d), (v3 - v4) / (2 * d)}};
        CHECK(kf.vx() == Approx(j[0][0] * before.vx() + j[0][1] * before.vy()).epsilon(1e-4));
        CHECK(kf.vy() == Approx(j[1][0] * before.vx() + j[1][1] * before.vy()).epsilon(1e-4));
        // P ← T P Tᵀ, T = diag(J, J), in double.
        double t[4][4] = {}, want[4][4] = {};
        for (int b = 0; b < 4; b += 2)
            for (int r = 0; r < 2; ++r)
                for (int c = 0; c < 2; ++c) t[b + r][b + c] = j[r][c];
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                for (int k = 0; k < 4; ++k)
                    for (int l = 0; l < 4; ++l) want[r][c] += t[r][k] * before.p(k, l) * t[c][l];
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                INFO("P(" << r << ", " << c << ")");
                CHECK(std::abs(kf.p(r, c) - want[r][c]) <=
                      1e-4 * std::sqrt(want[r][r] * want[c][c]));
            }
        // homography_jacobian itself against the finite differences.
        float jf[4];
        REQUIRE(homography_jacobian(h, before.x(), before.y(), jf));
        CHECK(jf[0] == Approx(j[0][0]).epsilon(1e-4));
        CHECK(jf[1] == Approx(j[0][1]).margin(1e-5));
        CHECK(jf[2] == Approx(j[1][0]).margin(1e-5));
        CHECK(jf[3] == Approx(j[1][1]).epsilon(1e-4));
    }
}

TEST_CASE(
    "TargetTracker fused: a stationary target carried by translations, out of view, reacquired, "
    "reset",
    "[target]") {
    // Q = diag(1, 1, 0.01, 0.01) and reset_det_s = 400 (set here, not the default): det S
    // starts far above 400 after the frames unseen and falls below it after a few measurements.
    TargetTrackerParams params;
    params.kalman.q_pos = 1;
    params.kalman.q_vel = 0.01f;
    params.reset_det_s = 400;
    TargetTracker t;
    t.init(299.5f, 100.0f, 320, 240, params);
    REQUIRE(t.state() == TargetState::measured);
    // Frames 1..12: the camera moves so that the ground shifts +2 px/frame in x; nothing
    // measured. The filter's velocity stays exactly 0 (no update), so the reported position is
    // A x̂ = 299.5 + 2k exactly (sums of small integers and halves are exact in float). The
    // image covers x in [−0.5, 319.5): frame 9 is at 317.5 (inside), frame 10 at 319.5 (outside).
    for (int k = 1; k <= 12; ++k) {
        const SearchWindow w = t.predict(geometry(translation(2, 0)));
        CHECK(w.x == 299.5f + 2.0f * k);
        CHECK(w.y == 100.0f);
        CHECK(w.radius >= params.min_radius_px);
        const TargetEstimate e = t.update(kNone);
        INFO("frame " << k);
        CHECK(e.x == 299.5f + 2.0f * k);
        CHECK(e.y == 100.0f);
        CHECK(e.unseen == k);
        CHECK_FALSE(e.reset);
        CHECK(e.state == (k <= 9 ? TargetState::predicted : TargetState::out_of_view));
    }
    CHECK(t.accumulated().m[2] == 24.0f);
    // Frames 13..: the ground moves back, −2 px/frame: 321.5 (out), 319.5 (out), 317.5 (in), ...
    int k = 13;
    for (; k <= 15; ++k) {
        t.predict(geometry(translation(-2, 0)));
        const TargetEstimate e = t.update(kNone);
        CHECK(e.x == 299.5f + 24.0f - 2.0f * (k - 12));
        CHECK(e.state == (k <= 14 ? TargetState::out_of_view : TargetState::predicted));
    }
    // Frame 16: predicted at 315.5; a match 0.5 px off comes back. 16 frames without a
    // measurement made S huge (P_xx alone > 100), so the NDS is tiny: accepted, reacquired;
    // det S > 400, so no reset yet.
    const SearchWindow w16 = t.predict(geometry(translation(-2, 0)));
    CHECK(w16.x == 315.5f);
    TargetEstimate e = t.update(seen(316.0f, 99.7f));
    CHECK(e.state == TargetState::reacquired);
    CHECK(e.unseen == 0);
    CHECK(e.nds < 0.01f);
    CHECK(e.det_s > 400.0f);
    CHECK_FALSE(e.reset);
    CHECK(e.x == Approx(316.0f).margin(0.05));  // the filter trusts the measurement
    // Then a match exactly where predicted every frame: measured, and as S shrinks the reset
    // rule fires exactly when D_nds <= 5.99 and det S <= 400 (Table III).
    bool reset_seen = false;
    for (++k; k <= 60 && !reset_seen; ++k) {
        const SearchWindow w = t.predict(geometry(translation(-2, 0)));
        const float before_x = w.x, before_y = w.y;
        e = t.update(seen(w.x, w.y));
        INFO("frame " << k << " nds " << e.nds << " det S " << e.det_s);
        CHECK(e.state == TargetState::measured);
        CHECK(e.reset == (e.nds <= params.reset_nds && e.det_s <= params.reset_det_s));
        if (e.reset) {
            reset_seen = true;
            // A becomes the identity and the filter now lives in this frame's image: the
            // reported position is continuous across the reset (A x̂ before = x̂ after).
            CHECK(is_identity(t.accumulated()));
            CHECK(e.x == Approx(before_x).margin(1e-3));
            CHECK(e.y == Approx(before_y).margin(1e-3));
        } else {
            CHECK_FALSE(is_identity(t.accumulated()));
        }
    }
    CHECK(reset_seen);
    // After the reset the next frame's translation moves the window by exactly −2 px plus the
    // filter's own velocity (A = that one translation).
    TargetTracker copy = t;
    const SearchWindow next = copy.predict(geometry(translation(-2, 0)));
    float px = 0, py = 0;
    apply_homography(translation(-2, 0), e.x, e.y, px, py);
    CHECK(next.x == Approx(px).margin(0.5));  // velocity ~0 for a stationary target
    CHECK(copy.accumulated().m[2] == -2.0f);
}

// The track a leaving target coasts on, in double: x = (ax + bx·t) / (1 + c·t), y alike, t =
// k − k̄ (frame k, k̄ the samples' mean frame: the residual below is the track's error weighted
// by 1 + c·t, which depends on the origin of t), by least squares on ax + bx·t − c·t·x = x (and
// y) over the samples (k, x, y) of the window's frames (coast frame − window .. coast frame),
// solved as one 5 × 5 normal system by Gaussian elimination (the tracker eliminates a and b in
// closed form instead, about the means of t, x and y, in float). projective false: c = 0, the
// least-squares line.
struct RefTrack {
    double ax = 0, bx = 0, ay = 0, by = 0, c = 0, km = 0;
    RefTrack(const std::vector<int>& frames, const std::vector<double>& xs,
             const std::vector<double>& ys, int coast_frame, int window, bool projective) {
        double count = 0;
        for (size_t i = 0; i < frames.size(); ++i)
            if (coast_frame - frames[i] <= window) {
                km += frames[i];
                count += 1;
            }
        km /= count;
        const int n = projective ? 5 : 4;  // unknowns ax, bx, ay, by[, c]
        double m[5][6] = {};
        auto add = [&](const double row[5], double rhs) {
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) m[i][j] += row[i] * row[j];
                m[i][5] += row[i] * rhs;
            }
        };
        for (size_t i = 0; i < frames.size(); ++i) {
            if (coast_frame - frames[i] > window) continue;
            const double k = frames[i] - km;
            const double rx[5] = {1, k, 0, 0, -k * xs[i]}, ry[5] = {0, 0, 1, k, -k * ys[i]};
            add(rx, xs[i]);
            add(ry, ys[i]);
        }
        for (int col = 0; col < n; ++col) {
            int pivot = col;
            for (int r = col + 1; r < n; ++r)
                if (std::fabs(m[r][col]) > std::fabs(m[pivot][col])) pivot = r;
            for (int j = 0; j < 6; ++j) std::swap(m[col][j], m[pivot][j]);
            for (int r = 0; r < n; ++r) {
                if (r == col) continue;
                const double f = m[r][col] / m[col][col];
                for (int j = 0; j < 6; ++j) m[r][j] -= f * m[col][j];
            }
        }
        ax = m[0][5] / m[0][0];
        bx = m[1][5] / m[1][1];
        ay = m[2][5] / m[2][2];
        by = m[3][5] / m[3][3];
        if (projective) c = m[4][5] / m[4][4];
    }
    double x(int k) const { return (ax + bx * (k - km)) / (1 + c * (k - km)); }
    double y(int k) const { return (ay + by * (k - km)) / (1 + c * (k - km)); }
};

// The camera moves the ground +2 px a frame in x. The target starts at (120, 100) and drives
// over the ground; its track in the image of frame 0 is track(k). Frames 1..50 measure it with
// a deterministic zero-mean error (±0.6 px in x alternating, −0.4/0/+0.4 in y); then nothing.
// Every measurement is in the image the filter lives in after its reset, so the reference is
// fitted in frame-0 coordinates with the ground motion taken out (frames, gx, gy). out: the
// estimates of frames 51..110.
template <class Track>
void run_leaving_target(const TargetTrackerParams& params, Track&& track, std::vector<int>& frames,
                        std::vector<double>& gx, std::vector<double>& gy,
                        std::vector<TargetEstimate>& out) {
    TargetTracker t;
    t.init(120, 100, 320, 240, params);
    frames.assign(1, 0);
    gx.assign(1, 120.0);
    gy.assign(1, 100.0);
    out.clear();
    for (int k = 1; k <= 110; ++k) {
        t.predict(geometry(translation(2, 0)));
        if (k <= 50) {
            double x = 0, y = 0;
            track(k, x, y);
            const double zx = x + 2.0 * k + (k % 2 == 0 ? 0.6 : -0.6), zy = y + 0.4 * (k % 3 - 1);
            const TargetEstimate e = t.update(seen(static_cast<float>(zx), static_cast<float>(zy)));
            REQUIRE(e.state == TargetState::measured);
            frames.push_back(k);
            gx.push_back(zx - 2.0 * k);  // the ground track: camera motion taken out
            gy.push_back(zy);
        } else {
            out.push_back(t.update(kNone));
        }
    }
}

// The worst error of the estimates of frames `from`..110 (out holds frames 51..110) against the
// track carried into each frame by the ground's motion, px.
template <class Track>
double worst_error(const std::vector<TargetEstimate>& out, int from, Track&& track) {
    double worst = 0;
    for (int k = from; k <= 110; ++k) {
        const TargetEstimate& e = out[static_cast<size_t>(k - 51)];
        double tx = 0, ty = 0;
        track(k, tx, ty);
        worst = std::max(worst, std::hypot(e.x - (tx + 2.0 * k), e.y - ty));
    }
    return worst;
}

// From the first frame out of view on, the estimates lie on `ref` carried into the frame by
// the ground's motion; returns the worst error against the truth track over those frames.
template <class Track>
double check_coasting(const std::vector<TargetEstimate>& out, const std::vector<int>& frames,
                      const std::vector<double>& gx, const std::vector<double>& gy,
                      const TargetTrackerParams& params, Track&& track, double margin_px) {
    int coast = -1;
    for (size_t i = 0; i < out.size() && coast < 0; ++i)
        if (out[i].state == TargetState::out_of_view) coast = static_cast<int>(i) + 51;
    REQUIRE(coast > 51);
    const RefTrack ref(frames, gx, gy, coast, params.coast_fit_frames, params.coast_projective);
    for (int k = coast; k <= 110; ++k) {
        const TargetEstimate& e = out[static_cast<size_t>(k - 51)];
        INFO("frame " << k);
        CHECK(e.state == TargetState::out_of_view);
        CHECK(e.x == Approx(ref.x(k) + 2.0 * k).margin(margin_px));
        CHECK(e.y == Approx(ref.y(k)).margin(margin_px));
    }
    return worst_error(out, coast, track);
}

TEST_CASE(
    "TargetTracker fused, straight coasting: a target leaving the image coasts on the "
    "least-squares line through its last measurements",
    "[target]") {
    // A straight ground track at constant speed: (120 + 1.5k, 100 + 0.5k).
    auto track = [](int k, double& x, double& y) {
        x = 120 + 1.5 * k;
        y = 100 + 0.5 * k;
    };
    TargetTrackerParams params;
    params.coast_projective = false;
    params.coast_fit_frames = 32;
    std::vector<int> frames;
    std::vector<double> gx, gy;
    std::vector<TargetEstimate> coasted, kalman;
    run_leaving_target(params, track, frames, gx, gy, coasted);
    const double worst_coasted = check_coasting(coasted, frames, gx, gy, params, track, 2e-3);
    TargetTrackerParams paper = params;
    paper.coast_fit_frames = 0;
    run_leaving_target(paper, track, frames, gx, gy, kalman);
    const double worst_kalman = worst_error(kalman, 51, track);
    // The line through 32 frames of measurements against the filter's own velocity: the
    // measurement error hardly moves the line, while the filter's velocity follows the last
    // measurements' errors (Q's 1 px²/frame² lets it).
    INFO("worst error out of view: coasting " << worst_coasted << " px, the filter's velocity "
                                              << worst_kalman << " px");
    CHECK(worst_coasted < 1.0);
    CHECK(worst_kalman > 2 * worst_coasted);
}

TEST_CASE(
    "TargetTracker fused: a target leaving the image coasts on the perspective track fitted "
    "to its last measurements, where a straight line falls behind",
    "[target]") {
    // Constant velocity on a plane seen in perspective: the ground point's depth grows
    // linearly, 1 + 0.006k, so the image track slows down along a straight line:
    // (120 + 2.5k, 100 + 0.8k) / (1 + 0.006k) about (0, 0), plus the camera's 2k in x. It
    // leaves the image near frame 61.
    auto track = [](int k, double& x, double& y) {
        const double d = 1 + 0.006 * k;
        x = (120 + 2.5 * k) / d;
        y = (100 + 0.8 * k) / d;
    };
    const TargetTrackerParams params;  // defaults: coast_projective, coast_fit_frames 63
    REQUIRE(params.coast_projective);
    std::vector<int> frames;
    std::vector<double> gx, gy;
    std::vector<TargetEstimate> projective, straight;
    run_leaving_target(params, track, frames, gx, gy, projective);
    // Float against double over a fit of 51 samples, carried up to 60 frames on: 2e-3 px.
    const double worst_projective = check_coasting(projective, frames, gx, gy, params, track, 2e-3);
    TargetTrackerParams line = params;
    line.coast_projective = false;
    run_leaving_target(line, track, frames, gx, gy, straight);
    const double worst_straight = check_coasting(straight, frames, gx, gy, line, track, 2e-3);
    INFO("worst error out of view: perspective track " << worst_projective << " px, straight line "
                                                       << worst_straight << " px");
    CHECK(worst_projective < 1.0);
    CHECK(worst_straight > 4 * worst_projective);
}

TEST_CASE("TargetTracker fused with the default parameters resets on a perfect measurement",
          "[target]") {
    // Table III: reset when D_nds and det S are "reasonably small". Defaults: Q = diag(20, 20,
    // 1, 1), r = 4. After predict, S = H P̄ Hᵀ + R with P̄ = Φ P Φᵀ + Q, so S − (q_pos + r) I
    // is positive semi-definite and det S >= (20 + 4)² = 576 for every state (J = I here): the
    // default reset_det_s must lie above that or the reset never fires (it was 400 at first;
    // this case found it). A stationary target measured exactly at its prediction every frame
    // for 50 frames (the tightest S there is).
    TargetTracker t;
    t.init(100, 100, 320, 240, TargetTrackerParams{});
    bool reset_seen = false;
    float min_det = 1e30f;
    for (int k = 0; k < 50; ++k) {
        const SearchWindow w = t.predict(geometry(translation(1, 0)));
        const TargetEstimate e = t.update(seen(w.x, w.y));
        REQUIRE(e.state == TargetState::measured);
        min_det = std::min(min_det, e.det_s);
        reset_seen = reset_seen || e.reset;
    }
    INFO("smallest det S " << min_det << " px^4, reset_det_s "
                           << TargetTrackerParams{}.reset_det_s);
    CHECK(min_det >= 576.0f);
    CHECK(reset_seen);
}

TEST_CASE("TargetTracker gates: NDS, reprojection error, score", "[target]") {
    // One frame after init at (100, 100) with the defaults and an identity homography:
    // P̄_xx = r + p0_vel + q_pos = 4 + 4 + 20 = 28, S = diag(32, 32), so D_nds = d²/32.
    const TargetTrackerParams params;
    auto first_frame = [&](const FrameGeometry& g, const TargetMeasurement& m) {
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        t.predict(g);
        return t.update(m);
    };
    SECTION("D_nds = d²/32 against gate_nds = 9.21") {
        TargetEstimate e = first_frame(geometry(Homography{}), seen(150, 100));  // 2500/32
        CHECK(e.nds == Approx(78.125));
        CHECK(e.state == TargetState::predicted);
        CHECK(e.unseen == 1);
        CHECK(e.x == 100.0f);                                     // the estimate did not move
        e = first_frame(geometry(Homography{}), seen(100, 118));  // 324/32 = 10.125 > 9.21
        CHECK(e.nds == Approx(10.125));
        CHECK(e.state == TargetState::predicted);
        e = first_frame(geometry(Homography{}), seen(100, 117));  // 289/32 = 9.03 <= 9.21
        CHECK(e.nds == Approx(9.03125));
        CHECK(e.state == TargetState::measured);
        // K = P̄ S⁻¹ = 28/32 on the position: 100 + 0.875·17.
        CHECK(e.y == Approx(100 + 0.875 * 17).epsilon(1e-6));
        CHECK(e.det_s == Approx(1024.0));
    }
    SECTION("a frame whose reprojection error exceeds gate_rep_px is not used for measurement") {
        TargetEstimate e = first_frame(geometry(Homography{}, 2.1f), seen(100, 100));
        CHECK(e.state == TargetState::predicted);
        CHECK(e.nds == 0.0f);  // the measurement was not even considered
        CHECK(e.unseen == 1);
        e = first_frame(geometry(Homography{}, 2.0f), seen(100, 100));  // <= 2.0: trusted
        CHECK(e.state == TargetState::measured);
        e = first_frame(geometry(Homography{}, 0.0f, false), seen(100, 100));  // failed estimate
        CHECK(e.state == TargetState::predicted);
        // An untrustworthy frame is carried by the last good homography: +2, then a "+5"
        // frame with 2.5 px of reprojection error counts as +2 again.
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        t.predict(geometry(translation(2, 0)));
        CHECK(t.update(kNone).x == 102.0f);
        t.predict(geometry(translation(5, 0), 2.5f));
        CHECK(t.update(kNone).x == 104.0f);
    }
    SECTION("a match with NCC below min_score is ignored") {
        TargetEstimate e = first_frame(geometry(Homography{}), seen(101, 100, 0.69f));
        CHECK(e.state == TargetState::predicted);
        CHECK(e.nds == 0.0f);
        e = first_frame(geometry(Homography{}), seen(101, 100, 0.7f));
        CHECK(e.state == TargetState::measured);
        TargetMeasurement not_found = seen(101, 100, 0.99f);
        not_found.found = false;
        CHECK(first_frame(geometry(Homography{}), not_found).state == TargetState::predicted);
    }
}

TEST_CASE("TargetTracker lost rules: unseen, bad geometry, implausible accumulation", "[target]") {
    const TargetTrackerParams params;
    SECTION("more than max_unseen frames without a measurement, then lost for good") {
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        for (int k = 1; k <= params.max_unseen; ++k) {
            t.predict(geometry(Homography{}));
            const TargetEstimate e = t.update(kNone);
            if (e.state != TargetState::predicted)
                FAIL("frame " << k << ": " << target_state_name(e.state));
        }
        t.predict(geometry(Homography{}));
        CHECK(t.update(kNone).state == TargetState::lost);  // frame max_unseen + 1
        // A perfect measurement does not revive it; the window is empty.
        const SearchWindow w = t.predict(geometry(Homography{}));
        CHECK(w.radius == 0.0f);
        CHECK(t.update(seen(100, 100)).state == TargetState::lost);
        CHECK(t.state() == TargetState::lost);
    }
    SECTION("more than max_bad_geometry invalid homographies in a row while unseen") {
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        for (int k = 1; k <= params.max_bad_geometry; ++k) {
            t.predict(geometry(Homography{}, 0, false));
            CHECK(t.update(kNone).state == TargetState::predicted);
        }
        // One good frame breaks the run: another max_bad_geometry bad ones are tolerated.
        t.predict(geometry(Homography{}));
        CHECK(t.update(kNone).state == TargetState::predicted);
        for (int k = 1; k <= params.max_bad_geometry; ++k) {
            t.predict(geometry(Homography{}, 5.0f));  // valid but untrustworthy
            CHECK(t.update(kNone).state == TargetState::predicted);
        }
        t.predict(geometry(Homography{}, 0, false));  // the 16th in a row
        CHECK(t.update(kNone).state == TargetState::lost);
        t.predict(geometry(Homography{}));
        CHECK(t.update(seen(100, 100)).state == TargetState::lost);
    }
    SECTION("A scaling the area at the estimate beyond max_scale² = 16") {
        // Scaling by 1.2 about the target each frame: area × 1.44^k; 1.44^7 = 12.8 <= 16 and
        // 1.44^8 = 18.5 > 16, so lost at frame 8 (and likewise 1/1.2 for a shrinking area).
        for (const float s : {1.2f, 1.0f / 1.2f}) {
            TargetTracker t;
            t.init(160, 120, 320, 240, params);
            for (int k = 1; k <= 7; ++k) {
                t.predict(geometry(scaling(s, 160, 120)));
                const TargetEstimate e = t.update(kNone);
                CHECK(e.state == TargetState::predicted);
                CHECK(e.x == Approx(160).margin(1e-3));  // the fixed point of the scaling
            }
            t.predict(geometry(scaling(s, 160, 120)));
            CHECK(t.update(kNone).state == TargetState::lost);
            t.predict(geometry(Homography{}));
            CHECK(t.update(kNone).state == TargetState::lost);
        }
    }
}

TEST_CASE("TargetTracker: a frame whose motion is unmeasured assumes the last trusted one",
          "[target]") {
    // The camera pans 3 px a frame over a still target: trusted homographies for 5 frames, then
    // frames with too few corners to measure the motion (a textureless stretch).
    const TargetTrackerParams params;
    FrameGeometry unmeasured;
    unmeasured.unmeasured = true;
    TargetTracker t;
    t.init(100, 100, 320, 240, params);
    float x = 100;
    for (int k = 1; k <= 5; ++k) {
        x += 3;
        t.predict(geometry(translation(3, 0)));
        REQUIRE(t.update(seen(x, 100)).state == TargetState::measured);
    }
    SECTION("the measurement is used, in the image the assumed motion gives") {
        for (int k = 1; k <= 40; ++k) {
            x += 3;
            t.predict(unmeasured);
            const TargetEstimate e = t.update(seen(x, 100));
            INFO("frame " << k);
            REQUIRE(e.state == TargetState::measured);
            CHECK(e.x == Approx(x).margin(0.5));
            CHECK(e.y == Approx(100).margin(0.5));
        }
    }
    SECTION("unseen, the estimate moves with the assumed motion and is not lost to bad geometry") {
        for (int k = 1; k <= 3 * params.max_bad_geometry; ++k) {
            x += 3;
            t.predict(unmeasured);
            const TargetEstimate e = t.update(kNone);
            INFO("frame " << k);
            REQUIRE(e.state == TargetState::predicted);
            CHECK(e.x == Approx(x).margin(0.5));
        }
    }
    SECTION("a homography that failed with pairs enough is evidence: the measurement is refused") {
        for (int k = 1; k <= params.max_bad_geometry; ++k) {
            x += 3;
            t.predict(geometry(Homography{}, 0, false));
            CHECK(t.update(seen(x, 100)).state == TargetState::predicted);
        }
        t.predict(geometry(Homography{}, 0, false));
        CHECK(t.update(seen(x + 3, 100)).state == TargetState::lost);
    }
}

TEST_CASE("TargetTracker lost rule: an estimate more than max_outside frames outside the image",
          "[target]") {
    // A static camera; the target measured moving right at 8 px a frame from x = 200 until it
    // leaves the 320-px image, then nothing: the estimate coasts on, out of view, until it is
    // more than one frame width (320 px) right of the image, x > 319.5 + 320 = 639.5 (by hand).
    // Lost there, reporting the last estimate within that reach, held: no frame reports a
    // position farther out.
    for (const float reach : {1.0f, 0.25f}) {
        TargetTrackerParams params;
        params.max_outside = reach;
        const float limit = 319.5f + reach * 320.0f;
        TargetTracker t;
        t.init(200, 100, 320, 240, params);
        float x = 200, lost_at = -1, held = 0;
        bool was_out = false;
        for (int k = 1; k <= 200; ++k) {
            t.predict(geometry(Homography{}));
            x += 8;
            const TargetEstimate e = t.update(x < 319 ? seen(x, 100) : kNone);
            INFO("reach " << reach << ", frame " << k << ": x " << e.x << ", "
                          << target_state_name(e.state));
            if (e.state == TargetState::out_of_view) was_out = true;
            CHECK(e.x <= limit);
            if (e.state == TargetState::lost && lost_at < 0) {
                lost_at = e.x;
                held = e.x;
            }
            if (lost_at >= 0) CHECK(e.x == held);
        }
        CHECK(was_out);
        REQUIRE(lost_at > 0);
        CHECK(lost_at > limit - 8.5f);  // the last estimate within reach: one step before it
    }
}

TEST_CASE("TargetTracker methods: homography only, filter only, template only", "[target]") {
    SECTION("homography_only: A applied to the start, radius 0, never measured") {
        TargetTrackerParams params;
        params.method = TargetMethod::homography_only;
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        for (int k = 1; k <= 10; ++k) {
            const SearchWindow w = t.predict(geometry(translation(3, -1)));
            CHECK(w.radius == 0.0f);
            CHECK(w.x == 100.0f + 3.0f * k);
            CHECK(w.y == 100.0f - 1.0f * k);
            const TargetEstimate e = t.update(seen(w.x, w.y, 1.0f));  // a perfect match, ignored
            float ax = 0, ay = 0;
            REQUIRE(apply_homography(t.accumulated(), 100, 100, ax, ay));
            CHECK(e.x == ax);
            CHECK(e.y == ay);
            CHECK(e.state == TargetState::predicted);
            CHECK(e.unseen == k);
        }
    }
    SECTION("filter_only: the geometry is ignored") {
        TargetTrackerParams params;
        params.method = TargetMethod::filter_only;
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        const SearchWindow w = t.predict(geometry(translation(30, 0)));
        CHECK(w.x == 100.0f);
        CHECK(w.radius > 0.0f);
        TargetEstimate e = t.update(kNone);
        CHECK(e.x == 100.0f);
        CHECK(e.state == TargetState::predicted);
        CHECK(is_identity(t.accumulated()));
        // A bad homography does not stop a measurement being used.
        t.predict(geometry(translation(30, 0), 9.0f, false));
        e = t.update(seen(102, 100));
        CHECK(e.state == TargetState::reacquired);
        CHECK(e.x > 100.0f);
        CHECK(e.x < 102.0f);
    }
    SECTION("template_only: follows the match anywhere, stays put without one") {
        TargetTrackerParams params;
        params.method = TargetMethod::template_only;
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        SearchWindow w = t.predict(geometry(translation(30, 0)));
        CHECK(w.x == 100.0f);
        CHECK(w.radius == params.template_radius_px);
        TargetEstimate e = t.update(seen(250, 30));  // 150 px away: no gate
        CHECK(e.state == TargetState::measured);
        CHECK(e.x == 250.0f);
        CHECK(e.y == 30.0f);
        w = t.predict(geometry(translation(30, 0)));
        CHECK(w.x == 250.0f);
        e = t.update(kNone);
        CHECK(e.state == TargetState::predicted);
        CHECK(e.x == 250.0f);
        CHECK(e.unseen == 1);
        t.predict(geometry(Homography{}));
        e = t.update(seen(251, 31));
        CHECK(e.state == TargetState::reacquired);
        CHECK(e.x == 251.0f);
    }
}

namespace {

// A smooth texture in double: a few sinusoids at 0.3–0.6 rad/px in different directions.
double texture(double x, double y) {
    return 128 + 45 * std::sin(0.55 * x + 0.2 * y + 0.3) +
           40 * std::sin(-0.25 * x + 0.5 * y + 1.1) + 25 * std::sin(0.35 * x + 0.4 * y + 2.0);
}
uint8_t grey(double v) {
    return static_cast<uint8_t>(std::lround(std::min(255.0, std::max(0.0, v))));
}

// A feature on pixel (px, py) whose 9×9 patch samples f(x − dx, y − dy): the content of f moved
// by (dx, dy).
template <class F>
Feature<4> feature_at(int px, int py, double dx, double dy, F f) {
    Feature<4> ft;
    ft.px = static_cast<int16_t>(px);
    ft.py = static_cast<int16_t>(py);
    for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c) ft.patch[r * 9 + c] = grey(f(px - 4 + c - dx, py - 4 + r - dy));
    return ft;
}

}  // namespace

TEST_CASE("match_displacement_q8 on patches of a smooth texture at sub-pixel shifts", "[target]") {
    // A's patch on pixel (px, py) of f; B's on (px + ox, py + oy) of f moved by (ox + dx, oy + dy),
    // so B's patch shows A's content moved by (dx, dy) within it: the displacement of A's
    // content into B is (ox + dx, oy + dy).
    double worst = 0;
    int checked = 0;
    const int starts[3][2] = {{20, 30}, {57, 11}, {3, 44}};
    for (const auto& s : starts)
        for (int ix = -5; ix <= 5; ++ix)
            for (int iy = -5; iy <= 5; ++iy) {
                const double dx = ix * 0.1, dy = iy * 0.1;
                const int ox = ix % 3 - 1, oy = 2 - iy % 2;  // integer offsets of B's pixel
                const Feature<4> a = feature_at(s[0], s[1], 0, 0, texture);
                const Feature<4> b = feature_at(s[0] + ox, s[1] + oy, ox + dx, oy + dy, texture);
                int32_t qx = 0, qy = 0;
                INFO("start (" << s[0] << ", " << s[1] << "), offset (" << ox << ", " << oy
                               << "), sub-pixel (" << dx << ", " << dy << ")");
                REQUIRE(match_displacement_q8(a, b, qx, qy));
                const double ex = qx / 256.0 - (ox + dx), ey = qy / 256.0 - (oy + dy);
                worst = std::max(worst, std::max(std::abs(ex), std::abs(ey)));
                ++checked;
            }
    INFO("worst error over " << checked << " displacements: " << worst << " px");
    WARN("match_displacement_q8 worst error " << worst << " px over " << checked << " cases");
    CHECK(worst < 0.06);  // measured 0.043 px (gradient by central differences, one LK step)
}

TEST_CASE("match_displacement_q8 refuses a flat patch and vertical stripes", "[target]") {
    int32_t qx = 0, qy = 0;
    // Flat: Σ E Eᵀ = 0.
    auto flat = [](double, double) { return 90.0; };
    CHECK_FALSE(match_displacement_q8(feature_at(10, 10, 0, 0, flat),
                                      feature_at(10, 10, 0.3, 0, flat), qx, qy));
    // Vertical stripes vary in x only: E_y = 0, det Σ E Eᵀ = 0 (the aperture problem).
    auto stripes = [](double x, double) { return 128 + 80 * std::sin(0.6 * x); };
    CHECK_FALSE(match_displacement_q8(feature_at(10, 10, 0, 0, stripes),
                                      feature_at(10, 10, 0.3, 0.2, stripes), qx, qy));
    // The same stripes with a weak horizontal component are accepted (the test is not vacuous).
    auto plaid = [](double x, double y) {
        return 128 + 80 * std::sin(0.6 * x) + 40 * std::sin(0.5 * y);
    };
    CHECK(match_displacement_q8(feature_at(10, 10, 0, 0, plaid),
                                feature_at(10, 10, 0.3, 0.2, plaid), qx, qy));
}

namespace {

// Matched pairs of a frame in which a moving object dominates: `object` pairs on it, moved by
// (12, 0) px relative to the ground, and `ground` pairs on the ground, which did not move (the
// camera is still). Both on a jittered grid over a 320 × 240 frame, 0.2 px of noise on B.
std::vector<PointPair> object_dominated_pairs(int object, int ground, uint64_t seed) {
    scene::Gaussian g{Pcg32(seed)};
    Pcg32 u(seed + 1);
    std::vector<PointPair> pairs;
    for (int i = 0; i < object + ground; ++i) {
        const bool on_object = i < object;
        // The object fills the left half, the ground the right half.
        const float ax = static_cast<float>((on_object ? 10 : 170) + u.below(140)),
                    ay = static_cast<float>(10 + u.below(220));
        const float dx = on_object ? 12.0f : 0.0f;
        pairs.push_back({ax, ay, ax + dx + 0.2f * static_cast<float>(g.next()),
                         ay + 0.2f * static_cast<float>(g.next())});
    }
    return pairs;
}

FrameGeometry geometry_of(const RansacResult& r) {
    FrameGeometry g;
    g.valid = r.status == HomographyStatus::ok;
    g.h = r.h;
    g.reprojection_px = r.reprojection_px;
    g.d_rep = r.d_rep;
    g.d_rep_capped_px = r.d_rep_capped_px;
    return g;
}

}  // namespace

TEST_CASE(
    "D_rep over the matched pairs (equation (7)) refuses a wrong but self-consistent homography: "
    "a moving object dominating the matches",
    "[target][drep]") {
    // 36 pairs on an object moving 12 px, 24 on the still ground: RANSAC's consensus is the
    // object's translation, wrong for the ground the tracker needs. Its inliers fit it within
    // the noise, so an RMS over the inliers (at most ~inlier_px·√2 by construction) looks fine.
    const std::vector<PointPair> pairs = object_dominated_pairs(36, 24, 77);
    const RansacResult r = estimate_homography(pairs.data(), static_cast<uint16_t>(pairs.size()),
                                               RansacParams{}, nullptr);
    REQUIRE(r.status == HomographyStatus::ok);
    REQUIRE(r.inliers == 36);
    CHECK(std::abs(r.h.m[2] - 12.0f) < 0.2f);  // the object's motion, not the ground's
    CHECK(r.reprojection_px < 0.3f);           // the inliers' RMS: nothing to see there
    // The reference: for a translation H, Sampson's error is exactly |H a − b|²/2 (J Jᵀ = 2 I);
    // in double with the H RANSAC returned, over all 60 pairs; the capped RMS with the cap
    // (2 · 2 px)² = 16 px².
    double sum = 0, capped = 0;
    for (const PointPair& p : pairs) {
        const double ex = p.ax + r.h.m[2] - p.bx, ey = p.ay + r.h.m[5] - p.by;
        const double e = (ex * ex + ey * ey) / 2;
        sum += e;
        capped += std::min(e, 16.0);
    }
    const double capped_px = std::sqrt(capped / 60);
    // H is a translation up to float rounding of the refit (h1, h5 ≈ 1, the rest ≈ 0).
    REQUIRE(std::abs(r.h.m[0] - 1) < 1e-3);
    REQUIRE(std::abs(r.h.m[6]) < 1e-5);
    CHECK(r.d_rep == Approx(sum).epsilon(0.02));
    CHECK(r.d_rep_capped_px == Approx(capped_px).epsilon(0.02));
    CHECK(sum > 1500);       // 24 ground pairs × 12²/2 = 1728 px²
    CHECK(capped_px > 2.4);  // √(24 · 16 / 60) = 2.53 px
    // Both gates refuse the frame: its homography carries nothing, its measurement is not used.
    TargetTrackerParams paper;
    paper.rep_gate = RepGate::paper;
    TargetTrackerParams capped_gate;  // the default
    REQUIRE(capped_gate.rep_gate == RepGate::capped);
    CHECK_FALSE(geometry_trusted(geometry_of(r), paper));
    CHECK_FALSE(geometry_trusted(geometry_of(r), capped_gate));
    for (const TargetTrackerParams& params : {paper, capped_gate}) {
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        t.predict(geometry_of(r));
        const TargetEstimate e = t.update(seen(100, 100));
        CHECK(e.state == TargetState::predicted);
        CHECK(e.x == 100.0f);  // not moved by the object's 12 px
    }
    // The same object covering a tenth of the matches: the ground wins and both gates trust it.
    const std::vector<PointPair> ok_pairs = object_dominated_pairs(6, 54, 78);
    const RansacResult ok = estimate_homography(
        ok_pairs.data(), static_cast<uint16_t>(ok_pairs.size()), RansacParams{}, nullptr);
    REQUIRE(ok.status == HomographyStatus::ok);
    float gx = 0, gy = 0;  // a ground point stays where it was
    REQUIRE(apply_homography(ok.h, 240, 120, gx, gy));
    CHECK(std::hypot(gx - 240, gy - 120) < 0.2f);
    CHECK(geometry_trusted(geometry_of(ok), paper));
    CHECK(geometry_trusted(geometry_of(ok), capped_gate));
}

TEST_CASE(
    "The paper's formulation: unseen, x_n = A x_m (equation (11)), and without the reset m stays 0 "
    "and the accumulated error stays (Fig. 12)",
    "[target][fig12]") {
    for (const bool reset : {true, false}) {
        TargetTrackerParams params;
        params.formulation = TargetFormulation::paper;
        params.reset = reset;
        TargetTracker t;
        t.init(100, 100, 320, 240, params);
        // Frames 1..5: the camera moves the ground +1 px/frame in x; the target moves with the
        // ground and 1 px/frame in y of its own, measured exactly.
        for (int k = 1; k <= 5; ++k) {
            t.predict(geometry(translation(1, 0)));
            const TargetEstimate e = t.update(seen(100.0f + k, 100.0f + k));
            REQUIRE(e.state == TargetState::measured);
            // The filter lives in the current image: the estimate stays near the measurement.
            CHECK(std::abs(e.x - (100.0f + k)) < 1.0f);
            CHECK(e.reset == (reset && e.det_s <= params.reset_det_s && e.nds <= params.reset_nds));
            if (k == 5) REQUIRE(e.reset == reset);  // exact measurements: small D_nds, det S
        }
        // Frames 6..15: hidden; the ground moves +2 px/frame. Equation (11): the reference
        // point x_m of the last reset frame carried by A, exactly (translations add exactly).
        float ref_x = 100, ref_y = 100;  // without the reset: frame 0's point
        if (reset) {
            // The last frame whose measurement reset the accumulation is frame 5: x_m is the
            // filter's estimate then, and A starts there.
            TargetTracker probe = t;
            const TargetEstimate r = probe.update(kNone);  // A = I straight after the reset
            ref_x = r.x;
            ref_y = r.y;
            CHECK(ref_y == Approx(105).margin(1.0));  // frame 5's estimate: the target's own 5 px
        }
        float acc_dx = reset ? 0.0f : 5.0f;  // frames 1..5 moved +1 each
        for (int k = 6; k <= 15; ++k) {
            t.predict(geometry(translation(2, 0)));
            acc_dx += 2.0f;
            const TargetEstimate e = t.update(kNone);
            INFO("reset " << reset << " frame " << k);
            CHECK(e.state == TargetState::predicted);
            CHECK(e.x == Approx(ref_x + acc_dx).margin(1e-3));
            CHECK(e.y == Approx(ref_y).margin(1e-3));  // no motion of the target's own
            // Without the reset, the target's own 5 px in y since frame 0 are lost as well.
            if (!reset) CHECK(e.y == 100.0f);
        }
    }
}

TEST_CASE(
    "The paper's search region: four corners x̂ ± 3σ mapped by A, carried while unseen, no "
    "search until inside the image, re-initialised on return",
    "[target][roi]") {
    TargetTrackerParams params;
    params.region = SearchRegionShape::paper;
    TargetTracker t;
    t.init(300, 100, 320, 240, params);
    // First frame, identity: P̄ = 28 I, S = 32 I: corners 300 ± 3·√32, 100 ± 3·√32.
    const float h = 3.0f * std::sqrt(32.0f);
    SearchWindow w = t.predict(geometry(Homography{}));
    REQUIRE(w.corners);
    CHECK(w.cx[0] == Approx(300 - h));
    CHECK(w.cx[1] == Approx(300 + h));
    CHECK(w.cy[0] == Approx(100 - h));
    CHECK(w.cy[2] == Approx(100 + h));
    CHECK(w.x == Approx(300));
    CHECK(w.radius == Approx(h));  // 16.97 px: inside [4, 24], as sized
    REQUIRE(t.update(kNone).state == TargetState::predicted);
    // Unseen: the region is carried by the frame's homography (+3 px in x), not resized by the
    // growing covariance. Its right side (300 + h + 3k) leaves the image (x >= 319.5) from
    // k = 1: no search while any corner is outside.
    for (int k = 1; k <= 4; ++k) {
        w = t.predict(geometry(translation(3, 0)));
        INFO("frame " << k);
        CHECK(w.cx[1] == Approx(300 + h + 3.0f * k));
        CHECK(w.cx[0] == Approx(300 - h + 3.0f * k));
        CHECK(w.radius == 0.0f);
        t.update(kNone);
    }
    // The ground moves back −6 px/frame: after 2 frames the region is at 300 ± h again, wholly
    // inside: searched, with the carried size.
    t.predict(geometry(translation(-6, 0)));
    t.update(kNone);
    w = t.predict(geometry(translation(-6, 0)));
    CHECK(w.cx[1] == Approx(300 + h).margin(1e-3));
    CHECK(w.radius == Approx(h).margin(1e-3));
    // The target is found: the next frame's region is re-initialised from the state (centred on
    // the estimate, sized from the new S).
    const TargetEstimate e = t.update(seen(w.x + 1, w.y));
    REQUIRE(e.state == TargetState::reacquired);
    TargetTracker copy = t;
    w = copy.predict(geometry(Homography{}));
    CHECK(w.x == Approx(e.x + copy.update(kNone).x - e.x).margin(0.5));
    CHECK(w.radius > 0);
}

namespace {

TargetMeasurement searched_in_vain() {
    TargetMeasurement m;
    m.searched = true;
    return m;
}

// A target measured at (x0 - v·k, 60) for frames k = 1..5 of a 160 × 120 image with a still
// camera: it moves v px a frame to the left, and the filter has learnt that velocity.
TargetTracker walked_left(float x0, float v, const TargetTrackerParams& p) {
    TargetTracker t;
    t.init(x0, 60, 160, 120, p);
    for (int k = 1; k <= 5; ++k) {
        t.predict(geometry(Homography{}));
        REQUIRE(t.update(seen(x0 - v * static_cast<float>(k), 60)).state == TargetState::measured);
    }
    return t;
}

// e, the frame that restarted t on a match at (x, y): reacquired there, the next window centred
// there (a restart has no velocity), and a match there the next frame measured.
void check_restarted_at(TargetTracker& t, const TargetEstimate& e, float x, float y) {
    CHECK(e.state == TargetState::reacquired);
    CHECK(e.x == x);
    CHECK(e.y == y);
    CHECK(e.unseen == 0);
    const SearchWindow w = t.predict(geometry(Homography{}));
    CHECK(w.x == Approx(x).margin(1e-3));
    CHECK(w.y == Approx(y).margin(1e-3));
    CHECK(t.update(seen(x, y)).state == TargetState::measured);
}

// Frames of `g` with `m` until the state is no longer predicted (at most 100): the last
// estimate.
TargetEstimate until_not_predicted(TargetTracker& t, const FrameGeometry& g,
                                   const TargetMeasurement& m) {
    TargetEstimate e;
    for (int k = 0; k < 100; ++k) {
        t.predict(g);
        e = t.update(m);
        if (e.state != TargetState::predicted) break;
    }
    return e;
}

}  // namespace

TEST_CASE(
    "An unconfirmed exit is lost: the target predicted out of the image by its own motion, "
    "the camera keeping its last measured position inside",
    "[target][lost]") {
    TargetTrackerParams p;
    p.max_outside = 100;  // the reach rule out of the way
    SECTION(
        "searched in vain, predicted out on the left: lost at the exit, reported where it was "
        "last measured") {
        TargetTracker t = walked_left(60, 5, p);  // last measured at x = 35
        TargetEstimate e;
        int frames = 0;
        do {
            t.predict(geometry(Homography{}));
            e = t.update(searched_in_vain());
            ++frames;
        } while (e.state == TargetState::predicted && frames < 100);
        // More than max_unconfirmed_exit (3) frames in vain before the estimate leaves: at
        // about 5 px a frame from x = 35, the exit comes after 7 or 8 frames.
        CHECK(frames > p.max_unconfirmed_exit);
        CHECK(e.state == TargetState::lost);
        CHECK(e.x == Approx(35).margin(0.01));
        CHECK(e.y == Approx(60).margin(0.01));
        // Lost stays lost, the position held, and with lost_search_px 0 nothing is searched.
        const SearchWindow w = t.predict(geometry(Homography{}));
        CHECK(w.radius == 0);
        CHECK(t.update(seen(35, 60)).state == TargetState::lost);
    }
    SECTION("the rule off: out of view, as before") {
        p.max_unconfirmed_exit = kCheckOff;
        TargetTracker t = walked_left(60, 5, p);
        CHECK(until_not_predicted(t, geometry(Homography{}), searched_in_vain()).state ==
              TargetState::out_of_view);
    }
    SECTION("frames not searched (the template across the border) do not count") {
        TargetTracker t = walked_left(60, 5, p);
        CHECK(until_not_predicted(t, geometry(Homography{}), kNone).state ==
              TargetState::out_of_view);
    }
    SECTION("a still target carried out by the camera: out of view, not lost") {
        TargetTracker t = walked_left(35, 0, p);
        // The image content moves 6 px a frame to the left: the last measured position leaves
        // with the estimate.
        CHECK(until_not_predicted(t, geometry(translation(-6, 0)), searched_in_vain()).state ==
              TargetState::out_of_view);
    }
}

TEST_CASE(
    "A target lost by an unconfirmed exit is searched for in a growing window around its "
    "last measured position, and a match restarts it",
    "[target][lost]") {
    TargetTrackerParams p;
    p.max_outside = 100;
    p.lost_search_px = 2;
    TargetTracker t = walked_left(60, 5, p);
    TargetEstimate e = until_not_predicted(t, geometry(Homography{}), searched_in_vain());
    REQUIRE(e.state == TargetState::lost);
    // The window: centred where it was last measured, min_radius + 2 px per lost frame, up to
    // max_radius (4 + 2 k, k = 1, 2, ...; 24 from k = 10).
    for (int k = 1; k <= 12; ++k) {
        const SearchWindow w = t.predict(geometry(Homography{}));
        CHECK(w.x == Approx(35).margin(0.01));
        CHECK(w.y == Approx(60).margin(0.01));
        CHECK(w.radius == Approx(k < 10 ? 4.0f + 2.0f * static_cast<float>(k) : 24.0f));
        e = t.update(searched_in_vain());
        CHECK(e.state == TargetState::lost);
    }
    // A match below min_score leaves it lost; one above restarts the filter there, with no
    // velocity: the next window is centred on the match.
    t.predict(geometry(Homography{}));
    CHECK(t.update(seen(40, 62, p.min_score - 0.05f)).state == TargetState::lost);
    t.predict(geometry(Homography{}));
    check_restarted_at(t, t.update(seen(40, 62)), 40, 62);
}

TEST_CASE(
    "look_at: the next window is there, carried by the camera, and only a match of the look's "
    "score restarts the track",
    "[target][redetect]") {
    TargetTrackerParams p;
    TargetTracker t = walked_left(100, 2, p);  // last measured at x = 90, 2 px a frame
    // Lost sight of: the filter's own prediction goes on (90 − 2k).
    for (int k = 0; k < 3; ++k) {
        t.predict(geometry(Homography{}));
        REQUIRE(t.update(searched_in_vain()).state == TargetState::predicted);
    }
    const TargetTracker before = t;
    SECTION("the window: the look's point moved by this frame's homography, the look's radius") {
        t.look_at(30, 40, 10, 0.85f);
        const SearchWindow w = t.predict(geometry(translation(5, -3)));
        CHECK(w.x == Approx(35).margin(1e-4));
        CHECK(w.y == Approx(37).margin(1e-4));
        CHECK(w.radius == 10);
        // Only the next frame: the one after is the prediction's again, as if no look had
        // been asked for.
        t.update(kNone);
        const SearchWindow next = t.predict(geometry(Homography{}));
        TargetTracker plain = before;
        plain.predict(geometry(translation(5, -3)));
        plain.update(kNone);
        const SearchWindow expected = plain.predict(geometry(Homography{}));
        CHECK(next.x == expected.x);
        CHECK(next.y == expected.y);
        CHECK(next.radius == expected.radius);
        CHECK(next.x > 80);  // the filter's, near x = 90 − 2·5 + 5, not the look's 35
    }
    SECTION("a match of the look's score restarts the filter there, with no velocity") {
        t.look_at(30, 40, 10, 0.85f);
        t.predict(geometry(Homography{}));
        check_restarted_at(t, t.update(seen(31, 41, 0.86f)), 31, 41);
    }
    SECTION("a match below the look's score (above min_score) is no measurement at all") {
        t.look_at(30, 40, 10, 0.85f);
        t.predict(geometry(Homography{}));
        const TargetEstimate e = t.update(seen(31, 41, 0.84f));
        // As a frame searched in vain: the filter neither restarted nor updated.
        TargetTracker vain = before;
        vain.predict(geometry(Homography{}));
        const TargetEstimate v = vain.update(searched_in_vain());
        CHECK(e.state == TargetState::predicted);
        CHECK(e.x == v.x);
        CHECK(e.y == v.y);
        CHECK(e.unseen == v.unseen);
    }
    SECTION("a lost target is restarted the same way") {
        p.max_unseen = 4;
        TargetTracker lost = walked_left(100, 2, p);
        for (int k = 0; k < 5; ++k) {
            lost.predict(geometry(Homography{}));
            lost.update(searched_in_vain());
        }
        REQUIRE(lost.state() == TargetState::lost);
        CHECK(lost.predict(geometry(Homography{})).radius == 0);  // lost: nothing searched
        lost.update(kNone);
        lost.look_at(120, 20, 8, 0.85f);
        const SearchWindow w = lost.predict(geometry(Homography{}));
        CHECK(w.x == 120);
        CHECK(w.radius == 8);
        check_restarted_at(lost, lost.update(seen(121, 22, 0.9f)), 121, 22);
    }
}

// The line tracker (core/tracking/line_tracker.h) and its turn filter (core/tracking/turn_kalman.h)
// against double-precision references written from the paper (§2.5–2.7) and from the turn model's
// equations, plus hand-worked cases: exact motion is predicted exactly, the near-origin cases the
// paper is about, and saturation over long spells without measurements.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "base/prng.h"
#include "tracking/line_tracker.h"
#include "tracking/turn_kalman.h"

using namespace qt;

namespace {

constexpr double kQ16 = 65536.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kTurn = 4294967296.0;  // binary angle units per turn

q16_16 q16(double v) { return q16_16::from_raw(std::llround(v * kQ16)); }
double val(q16_16 v) { return v.raw / kQ16; }
double theta_rad(angle_t a) { return a / kTurn * 2 * kPi; }

// A measured line n·p = rho (any sign, any angle), its segment of `len` px centred at the foot
// of (fx, fy), quantised the way the lines stage reports it (rho >= 0, theta in [0, 360°)).
Segment measure(double theta, double rho, double fx, double fy, double len = 80) {
    if (rho < 0) {
        rho = -rho;
        theta += kPi;
    }
    theta = std::fmod(theta, 2 * kPi);
    if (theta < 0) theta += 2 * kPi;
    const double nx = std::cos(theta), ny = std::sin(theta);
    const double d = nx * fx + ny * fy - rho;
    const double px = fx - d * nx, py = fy - d * ny;
    Segment s{};
    s.x1 = q16(px + ny * len / 2);
    s.y1 = q16(py - nx * len / 2);
    s.x2 = q16(px - ny * len / 2);
    s.y2 = q16(py + nx * len / 2);
    s.rho = q16(rho);
    s.theta = static_cast<angle_t>(static_cast<uint64_t>(std::llround(theta / (2 * kPi) * kTurn)) &
                                   0xFFFFFFFFu);
    s.cx = q16(rho * nx);
    s.cy = q16(rho * ny);
    return s;
}

// Largest distance, px, between two lines over the segment [-reach, reach] around (fx, fy).
double line_gap(double th_a, double rho_a, double th_b, double rho_b, double fx, double fy,
                double reach = 200) {
    const double nax = std::cos(th_a), nay = std::sin(th_a);
    const double d = nax * fx + nay * fy - rho_a;
    const double px = fx - d * nax, py = fy - d * nay;  // foot on line a
    double worst = 0;
    for (double t : {-reach, reach}) {
        const double x = px - nay * t, y = py + nax * t;
        worst = std::max(worst, std::fabs(std::cos(th_b) * x + std::sin(th_b) * y - rho_b));
    }
    return worst;
}

double gap_to(const Segment& s, double th, double rho, double fx, double fy, double reach = 200) {
    return line_gap(th, rho, theta_rad(s.theta), val(s.rho), fx, fy, reach);
}

// ---- reference: the paper's multiple-model filter in double --------------------------------
// One constant-velocity filter per axis (eqs. (3)–(5); the 4×4 form against this 2×2 one is
// tests/tracking/test_kalman.cpp's business), T_i, T_i⁻¹, and the total-least-squares line.
struct RefAxis {
    double x = 0, v = 0, a = 0, b = 0, c = 0;
    void init(double x0, double p0p, double p0v) { *this = RefAxis{x0, 0, p0p, 0, p0v}; }
    void predict(double q) {
        x += v;
        const double a1 = a + 2 * b + c + q / 4, b1 = b + c + q / 2, c1 = c + q;
        a = a1;
        b = b1;
        c = c1;
    }
    void update(double z, double r) {
        const double s = a + r, k1 = a / s, k2 = b / s, nu = z - x;
        x += k1 * nu;
        v += k2 * nu;
        const double a1 = a - k1 * a, b1 = b - k1 * b, c1 = c - k2 * b;
        a = a1;
        b = b1;
        c = c1;
    }
};

struct RefClosestPoints {
    int n = 3;
    double ox[3], oy[3];
    RefAxis ax[3], ay[3];
    double last_theta = 0;
    void set(const LineTrackerParams& p) {
        n = p.filters;
        for (int i = 0; i < 3; ++i) {
            ox[i] = val(p.origins[i].x);
            oy[i] = val(p.origins[i].y);
        }
    }
    void closest(const Segment& m, int i, double& cx, double& cy) const {
        const double th = theta_rad(m.theta),
                     r = val(m.rho) - std::cos(th) * ox[i] - std::sin(th) * oy[i];
        cx = r * std::cos(th);
        cy = r * std::sin(th);
    }
    void init(const Segment& m, const LineTrackerParams&) {
        for (int i = 0; i < n; ++i) {
            double cx, cy;
            closest(m, i, cx, cy);
            ax[i].init(cx, 0.5, 100);
            ay[i].init(cy, 0.5, 100);
        }
        last_theta = theta_rad(m.theta);
    }
    void predict() {
        for (int i = 0; i < n; ++i) {
            ax[i].predict(1);
            ay[i].predict(1);
        }
    }
    void update(const Segment& m) {
        for (int i = 0; i < n; ++i) {
            double cx, cy;
            closest(m, i, cx, cy);
            ax[i].update(cx, 0.5);
            ay[i].update(cy, 0.5);
        }
        last_theta = theta_rad(m.theta);
    }
    // The predicted line (normal angle, rho).
    void line(double& th, double& rho) const {
        if (n >= 2) {
            double mx = 0, my = 0;
            for (int i = 0; i < n; ++i) {
                mx += ox[i] + ax[i].x;
                my += oy[i] + ay[i].x;
            }
            mx /= n;
            my /= n;
            double sxx = 0, syy = 0, sxy = 0, spread = 0;  // spread: largest distance², px²
            for (int i = 0; i < n; ++i) {
                const double dx = ox[i] + ax[i].x - mx, dy = oy[i] + ay[i].x - my;
                sxx += dx * dx;
                syy += dy * dy;
                sxy += dx * dy;
                for (int j = i + 1; j < n; ++j)
                    spread = std::max(spread, std::pow(ox[i] + ax[i].x - ox[j] - ax[j].x, 2) +
                                                  std::pow(oy[i] + ay[i].x - oy[j] - ay[j].x, 2));
            }
            if (spread >= 64) {  // min_spread 8 px
                const double dir = 0.5 * std::atan2(2 * sxy, sxx - syy);
                th = dir + kPi / 2;
                rho = std::cos(th) * mx + std::sin(th) * my;
                return;
            }
        }
        int far = 0;
        for (int i = 1; i < n; ++i)
            if (std::hypot(ax[i].x, ay[i].x) > std::hypot(ax[far].x, ay[far].x)) far = i;
        th = std::hypot(ax[far].x, ay[far].x) >= 1 ? std::atan2(ay[far].x, ax[far].x) : last_theta;
        rho = std::cos(th) * (ox[far] + ax[far].x) + std::sin(th) * (oy[far] + ay[far].x);
    }
};

// ---- reference: the turn model in double ----------------------------------------------------
struct RefTurn {
    double axx, ayy;       // anchor
    RefAxis angle;         // degrees
    double x[3], p[3][3];  // ρ, ρ', ρ''
    double r_off, q_off, r_ang, q_ang;
    void set(const LineTrackerParams& lp) {
        axx = val(lp.turn.anchor.x);
        ayy = val(lp.turn.anchor.y);
        r_off = val(lp.turn.r_offset);
        q_off = val(lp.turn.q_offset);
        r_ang = val(lp.turn.r_angle);
        q_ang = val(lp.turn.q_angle);
    }
    void init(const Segment& m, const LineTrackerParams& lp) {
        double th = theta_rad(m.theta) * 180 / kPi;
        if (th >= 180) th -= 360;
        angle.init(th, r_ang, val(lp.turn.p0_turn));
        const double t = theta_rad(m.theta);
        x[0] = val(m.rho) - std::cos(t) * axx - std::sin(t) * ayy;
        x[1] = x[2] = 0;
        for (auto& row : p)
            for (double& e : row) e = 0;
        p[0][0] = r_off;
        p[1][1] = val(lp.turn.p0_rate);
        p[2][2] = val(lp.turn.p0_accel);
    }
    void predict() {
        const double w = std::clamp(angle.v, -45.0, 45.0) * kPi / 180;
        const double sinc = w == 0 ? 1 : std::sin(w) / w;
        const double oc = w == 0 ? 0.5 : (1 - std::cos(w)) / (w * w);
        const double A[3][3] = {
            {1, sinc, oc}, {0, std::cos(w), sinc}, {0, -w * std::sin(w), std::cos(w)}};
        const double g[3] = {1.0 / 6, 0.5, 1};
        double nx[3] = {0, 0, 0}, m[3][3] = {}, np[3][3] = {};
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) nx[i] += A[i][k] * x[k];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) m[i][j] += A[i][k] * p[k][j];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                np[i][j] = q_off * g[i] * g[j];
                for (int k = 0; k < 3; ++k) np[i][j] += m[i][k] * A[j][k];
            }
        for (int i = 0; i < 3; ++i) {
            x[i] = nx[i];
            for (int j = 0; j < 3; ++j) p[i][j] = np[i][j];
        }
        angle.predict(q_ang);
        if (angle.x >= 180) angle.x -= 360;
        if (angle.x < -180) angle.x += 360;
    }
    void update(const Segment& m) {
        double th = theta_rad(m.theta) * 180 / kPi;
        double d = std::remainder(th - angle.x, 360.0), sign = 1;
        if (d >= 90) {
            d -= 180;
            sign = -1;
        } else if (d < -90) {
            d += 180;
            sign = -1;
        }
        const double t = theta_rad(m.theta);
        const double z = sign * (val(m.rho) - std::cos(t) * axx - std::sin(t) * ayy);
        angle.update(angle.x + d, r_ang);
        const double s = p[0][0] + r_off, nu = z - x[0];
        double k[3], row0[3];
        for (int i = 0; i < 3; ++i) {
            k[i] = p[i][0] / s;
            row0[i] = p[0][i];
        }
        for (int i = 0; i < 3; ++i) x[i] += k[i] * nu;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) p[i][j] -= k[i] * row0[j];
    }
    void line(double& th, double& rho) const {
        th = angle.x * kPi / 180;
        rho = x[0] + std::cos(th) * axx + std::sin(th) * ayy;
    }
};

// A noisy trajectory: the normal turns by a slow sinusoid, rho drifts, end-point noise.
struct Trajectory {
    Pcg32 rng{12345};
    double uniform01() { return (rng.next() + 0.5) / 4294967296.0; }
    double theta(int k) const { return 0.7 + 0.4 * std::sin(k * 0.01) + k * 0.002; }
    double rho(int k) const { return 120 + 60 * std::sin(k * 0.013); }
    Segment at(int k) {
        const double noise_t = (uniform01() - 0.5) * 0.004, noise_r = (uniform01() - 0.5) * 0.6;
        return measure(theta(k) + noise_t, rho(k) + noise_r, 160, 120);
    }
};

// Runs the tracker and `ref` side by side over 10 000 frames of Trajectory: the largest gap,
// px over ±200 px, between their predicted lines. Requires no saturation flag at the end.
template <class Ref>
double worst_gap_to_reference(const LineTrackerParams& p, Ref& ref) {
    LineTracker tracker;
    ref.set(p);
    Trajectory traj;
    Segment m = traj.at(0);
    REQUIRE(tracker.init(m, p));
    ref.init(m, p);
    double worst = 0;
    for (int k = 1; k < 10000; ++k) {
        tracker.predict();
        ref.predict();
        double th, rho;
        ref.line(th, rho);
        worst = std::max(worst, gap_to(tracker.line(), th, rho, 160, 120));
        m = traj.at(k);
        tracker.update(m);
        ref.update(m);
    }
    CHECK(tracker.flags() == 0);
    return worst;
}

}  // namespace

TEST_CASE("turn transition: the series agree with sin and cos", "[line_tracker]") {
    for (int tenth = -450; tenth <= 450; tenth += 7) {
        const q16_16 deg = q16(tenth / 10.0);
        const double w = val(deg) * kPi / 180;
        const TurnTransition t = turn_transition(deg);
        const double sinc = w == 0 ? 1 : std::sin(w) / w,
                     oc = w == 0 ? 0.5 : (1 - std::cos(w)) / (w * w);
        CHECK(std::fabs(t.sinc.raw / 1073741824.0 - sinc) < 1e-8);
        CHECK(std::fabs(t.one_cos.raw / 1073741824.0 - oc) < 1e-8);
        CHECK(std::fabs(t.cos.raw / 1073741824.0 - std::cos(w)) < 1e-8);
        CHECK(std::fabs(t.w_sin.raw / 1073741824.0 - w * std::sin(w)) < 1e-8);
    }
}

TEST_CASE("line tracker: closest-point model follows the double reference for 10000 frames",
          "[line_tracker]") {
    for (int filters = 1; filters <= 3; ++filters) {
        LineTrackerParams p = default_line_tracker_params(320, 240);
        p.filters = static_cast<uint8_t>(filters);
        RefClosestPoints ref;
        const double worst = worst_gap_to_reference(p, ref);
        INFO("filters " << filters << ": largest gap " << worst << " px over ±200 px");
        CHECK(worst < 0.05);
    }
}

TEST_CASE("line tracker: turn model follows the double reference for 10000 frames",
          "[line_tracker]") {
    LineTrackerParams p = default_line_tracker_params(320, 240);
    p.model = LineModel::turn;
    RefTurn ref;
    const double worst = worst_gap_to_reference(p, ref);
    INFO("largest gap " << worst << " px over ±200 px");
    CHECK(worst < 0.05);
}

TEST_CASE("line tracker: exact motions are predicted exactly once the filters have settled",
          "[line_tracker]") {
    // Pure translation, 2 px/frame along the normal: every model's constant-velocity part is
    // exact. A turn of 6°/frame about (40, 30): only the turn model's transition is.
    struct Case {
        LineModel model;
        int filters;
        bool turning;
        double tol;
    };
    const Case cases[] = {{LineModel::closest_points, 1, false, 0.05},
                          {LineModel::closest_points, 3, false, 0.05},
                          {LineModel::turn, 3, false, 0.05},
                          {LineModel::turn, 3, true, 0.05}};
    for (const Case& c : cases) {
        LineTrackerParams p = default_line_tracker_params(320, 240);
        p.model = c.model;
        p.filters = static_cast<uint8_t>(c.filters);
        LineTracker tracker;
        auto truth = [&](int k, double& th, double& rho) {
            if (c.turning) {
                th = 0.3 + k * 6 * kPi / 180;
                rho = 50 + std::cos(th) * 40 + std::sin(th) * 30;  // 50 px from (40, 30)
            } else {
                th = 0.5;
                rho = 100 + 2.0 * k;
            }
        };
        double th, rho;
        truth(0, th, rho);
        tracker.init(measure(th, rho, 160, 120), p);
        double late = 0;
        for (int k = 1; k < 60; ++k) {
            truth(k, th, rho);
            tracker.predict();
            if (k >= 40) late = std::max(late, gap_to(tracker.line(), th, rho, 160, 120));
            tracker.update(measure(th, rho, 160, 120));
        }
        INFO("model " << static_cast<int>(c.model) << " filters " << c.filters << " turning "
                      << c.turning << ": prediction gap " << late << " px");
        CHECK(late < c.tol);
    }
}

TEST_CASE("line tracker: lines through a filter's origin (the paper's near-origin case)",
          "[line_tracker]") {
    // A line through the image origin, translating along x by 1 px/frame: filter 0's closest
    // point passes through r = 0. One filter alone keeps the last measured direction there;
    // three filters fit the line through the other two points and need no fallback.
    for (int filters : {1, 3}) {
        LineTrackerParams p = default_line_tracker_params(320, 240);
        p.filters = static_cast<uint8_t>(filters);
        LineTracker tracker;
        const double th = 1.1;  // normal direction; the line n·p = rho crosses 0 at k = 10
        auto rho_at = [&](int k) { return (k - 10) * 1.0 * std::cos(th); };
        tracker.init(measure(th, rho_at(0), 0, 0), p);
        double worst = 0;
        for (int k = 1; k < 25; ++k) {
            tracker.predict();
            if (k >= 4) worst = std::max(worst, gap_to(tracker.line(), th, rho_at(k), 0, 0, 100));
            tracker.update(measure(th, rho_at(k), 0, 0));
        }
        INFO(filters << " filters: worst gap " << worst << " px");
        CHECK(worst < 0.1);
    }
    // Two filters and a line perpendicular to O0O1 (vertical; the origins are (0,0) and (319,0)):
    // both closest points coincide, the fit has no direction, the polar fallback gives the line.
    LineTrackerParams p = default_line_tracker_params(320, 240);
    p.filters = 2;
    LineTracker tracker;
    tracker.init(measure(0, 100, 100, 100), p);
    for (int k = 1; k < 20; ++k) {
        tracker.predict();
        tracker.update(measure(0, 100 + k, 100, 100));
    }
    tracker.predict();
    CHECK(gap_to(tracker.line(), 0, 120, 100, 100) < 0.05);
}

TEST_CASE("line tracker: 100 frames without a measurement, then recovery", "[line_tracker]") {
    for (LineModel model : {LineModel::closest_points, LineModel::turn}) {
        LineTrackerParams p = default_line_tracker_params(320, 240);
        p.model = model;
        LineTracker tracker;
        tracker.init(measure(0.4, 100, 160, 120), p);
        for (int k = 1; k < 10; ++k) {
            tracker.predict();
            tracker.update(measure(0.4, 100 + 0.5 * k, 160, 120));
        }
        for (int k = 10; k < 110; ++k) tracker.predict();  // the side hidden for 100 frames
        // Constant velocity carried on: 0.5 px/frame for 100 more frames.
        CHECK(gap_to(tracker.line(), 0.4, 100 + 0.5 * 109, 160, 120) < 1.0);
        CHECK(tracker.flags() == 0);
        tracker.update(measure(0.4, 155, 160, 120));
        CHECK(gap_to(tracker.line(), 0.4, 155, 160, 120) < 0.5);
    }
}

TEST_CASE("turn filter: a long spell of prediction saturates and says so", "[line_tracker]") {
    TurnKalman f;
    f.init(q16(10), q16(0.5), q16(100), q16(4));
    for (int k = 0; k < 5; ++k) {
        f.predict(q16(3), q16(0.25));
        f.update(q16(10 + k), q16(0.5));
    }
    for (int k = 0; k < 20000; ++k) f.predict(q16(3), q16(1024));
    CHECK((f.flags() & TurnKalmanFlags::covariance_saturated) != 0);
    const int64_t* p = f.cov();
    for (int i : {0, 3, 5}) {
        CHECK(p[i] >= 0);
        CHECK(p[i] <= TurnKalman::kCovCeiling);
    }
    // Still positive semi-definite pairwise.
    CHECK(static_cast<double>(p[1]) * p[1] <= static_cast<double>(p[0]) * p[3] * 1.000001);
    f.update(q16(12), q16(0.5));
    CHECK(std::fabs(val(f.rho()) - 12) < 0.5);
}

TEST_CASE("line tracker: filters out of range are clamped and reported", "[line_tracker]") {
    LineTrackerParams p = default_line_tracker_params(320, 240);
    p.filters = 0;
    LineTracker tracker;
    CHECK_FALSE(tracker.init(measure(0.3, 50, 100, 100), p));
    p.filters = 4;
    CHECK_FALSE(tracker.init(measure(0.3, 50, 100, 100), p));
    p.filters = 3;
    CHECK(tracker.init(measure(0.3, 50, 100, 100), p));
}

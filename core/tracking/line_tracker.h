// The line tracker: the Quadrangle Detection paper §2.5–2.7 (the paper's multiple-model Kalman
// filter, "NKF") and, selectable beside it, a turn model of our own design.
//
// Lines are measured as Segments (rho >= 0, theta the normal's direction, pixels, y down) and
// reported the same way, so the quadrangle rules and intersect_lines() take them directly.
//
// closest_points (the paper, N = 1, 2 or 3 filters). Filter i has its own origin O_i. A
// measured line L is turned into the closest point of L to O_i, relative to O_i,
//   Z_i = T_i(L) = (rho − n·O_i)·n,  n = (cos θ, sin θ),
// tracked by PointKalman i (equations (3)–(5), constant velocity). The predictions are mapped
// back, P_i = T_i⁻¹(X_i) = O_i + (x_i, y_i), velocities dropped, and the line is the total
// least-squares fit through the P_i (fit_line). Near-origin case: P_i lies on the line whatever
// the distance from O_i, so for N >= 2 the fit only fails when the P_i (nearly) coincide — the
// line is perpendicular to O_1O_2 for N = 2 — and then, as for N = 1 always, the line is the
// polar line of the filter whose point lies farthest from its origin: through P_i with normal
// P_i − O_i. When even that is under min_radius from its origin (r ≈ 0: the line passes through
// the only origin), the normal's direction is undefined and the last measured direction is kept.
//
// turn (ours). The line's normal angle θ (degrees, continuous, sign of rho free) is tracked by
// one constant-velocity KalmanAxis (θ, ω = turn rate), and its signed distance ρ from an anchor
// point by TurnKalman (turn_kalman.h), whose transition bends with ω: exact for a line turning
// at a constant rate about any fixed point and for pure translation. Signed (θ, ρ) is continuous
// when the line crosses the anchor, so there is no near-origin case to handle.
//
// Use: init() on the first measurement; then every frame predict(), and update() when the line
// was measured in that frame. line() is the current estimate: after predict() the prediction
// for this frame, after update() the filtered line. Its end points are the last measured
// segment's end points projected onto the estimated line.
#pragma once
#include <stdint.h>

#include "lines/segment.h"
#include "quads/quad_rules.h"
#include "tracking/kalman.h"
#include "tracking/turn_kalman.h"

namespace qt {

enum class LineModel : uint8_t {
    closest_points,  // the paper's N Kalman filters on closest points, least-squares line
    turn,            // ours: angle with turn rate + offset bent by the turn rate
};

struct TurnParams {
    // Tuned on the experiment bench (bash bench.sh track-host, with --noise 0.5 as well): the
    // noise-free scores hardly depend on these; with 0.5 px of end-point noise smaller process
    // noise keeps the turn rate, whose error the lever arm to the anchor multiplies, steady.
    // Angle measurement variance, deg². A 100 px segment whose ends are known to ±0.5 px has
    // its angle known to about ±0.4°: 0.2 deg². Range [1/16, 1024].
    q16_16 r_angle = q16_16::from_ratio(1, 5);
    // Random angular acceleration per frame, variance in deg²/frame⁴. Range [0, 1024].
    q16_16 q_angle = q16_16::from_ratio(1, 50);
    // Offset measurement variance, px². Range [1/16, 1024].
    q16_16 r_offset = q16_16::from_int(1);
    // Random jerk of the offset per frame, variance in px²/frame⁶. Range [0, 1024].
    q16_16 q_offset = q16_16::from_ratio(1, 100);
    // Initial variances: angle rate (deg/frame)², offset rate (px/frame)², offset
    // acceleration (px/frame²)². Nothing is known at the first sighting; σ = 10°/frame,
    // 10 px/frame and 2 px/frame² cover hand-held motion. Range [0, 16384] each.
    q16_16 p0_turn = q16_16::from_int(100);
    q16_16 p0_rate = q16_16::from_int(100);
    q16_16 p0_accel = q16_16::from_int(4);
    // The point ρ is measured from, px. default_line_tracker_params() puts it at the frame's
    // centre, where the lines of a board in view pass close by, so ρ and its swing as the line
    // turns stay small.
    Point16 anchor = {q16_16::from_int(0), q16_16::from_int(0)};
};

struct LineTrackerParams {
    LineModel model = LineModel::closest_points;
    // closest_points: the number of filters N, 1..3 (the paper's 3KF is 3).
    uint8_t filters = 3;
    // closest_points: origin of filter i, px. Filter 0's is the image origin, the one a single
    // Hough-space tracker uses. See default_line_tracker_params() for the other two.
    Point16 origins[3] = {};
    KalmanParams kalman;  // each closest-point filter: the paper's q = 1, r = 0.5
    // closest_points: below this distance from its origin, px, a filter's point gives no
    // direction (the near-origin case).
    q16_16 min_radius = q16_16::from_int(1);
    // closest_points, N >= 2: the least-squares line needs two points at least this far apart,
    // px; closer, the polar line of the filter farthest from its origin is used instead. A
    // point's position error of 0.1 px turns a fit through points 8 px apart by 0.7°, about
    // what the polar line of a filter 8 px from its origin would be off by.
    q16_16 min_spread = q16_16::from_int(8);
    TurnParams turn;
};

// The defaults for a width × height frame. Origins (0, 0), (W − 1, 0) and ((W − 1)/2, H − 1):
// the image origin plus the two other corners of the widest triangle the frame holds with it,
// so that any line's three closest points (the origins' projections onto it) spread over at
// least min(H, ~W) pixels, and no line passes within min_radius of all three origins. The turn
// model's anchor is the frame's centre ((W − 1)/2, (H − 1)/2).
LineTrackerParams default_line_tracker_params(uint16_t width, uint16_t height);

// Flag bits of LineTracker::flags(): a filter saturated; the track should be dropped.
struct LineTrackerFlags {
    static constexpr uint8_t saturated = 1;
};

class LineTracker {
public:
    // Starts the track on `measured`. Returns false when params.filters was out of 1..3 (it is
    // clamped) or a filter clamped a parameter.
    bool init(const Segment& measured, const LineTrackerParams& params);
    void predict();
    void update(const Segment& measured);
    Segment line() const;
    uint8_t flags() const;
    // The variance of a measured line's distance from line() at the point p (px, on or near
    // the line): the estimate's variance across the line there plus the measurement's, px²
    // with 32 fraction bits, at most 2^58 (σ = 2^13 px). closest_points: the filters' largest
    // position variance plus r (the filters are predicted and updated together, so their
    // points are known equally well, and the fitted line as well as each of them). turn: the
    // offset's variance at the anchor plus the angle's times the squared distance, along the
    // line, of p from the anchor's foot (lever at most 4096 px), plus r_offset.
    int64_t innovation_variance(Point16 p) const;

    // Read-only views of the filters, for checking their covariances (tests, soak runs):
    // closest_points uses point_filter(0 .. params().filters − 1), turn the other two.
    const LineTrackerParams& params() const { return params_; }
    const PointKalman& point_filter(int i) const { return point_[i]; }
    const KalmanAxis& angle_filter() const { return angle_; }
    const TurnKalman& offset_filter() const { return offset_; }

private:
    int farthest_filter() const;  // the filter whose point lies farthest from its origin
    Segment polar_line(int i) const;
    Segment finish(angle_t theta, int64_t rho_raw) const;

    LineTrackerParams params_;
    PointKalman point_[3];    // closest_points
    KalmanAxis angle_{};      // turn: θ (deg), ω (deg/frame)
    TurnKalman offset_;       // turn: ρ from the anchor (px)
    Point16 ends_[2] = {};    // last measured end points, px
    angle_t last_theta_ = 0;  // last measured normal direction
    int8_t last_bright_ = 0;  // last measured Segment::bright_side
    uint8_t flags_ = 0;
};

}  // namespace qt

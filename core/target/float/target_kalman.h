// The target tracker's Kalman filter (the Filtering and Geometry paper Table II) in single
// precision:
//
//   x = [x, y, ẋ, ẏ]ᵀ (px, px/frame),  z = [x, y]ᵀ (px),  Δt = k − (k−1) = 1 frame,
//   Φ = [[1,0,1,0],[0,1,0,1],[0,0,1,0],[0,0,0,1]],  H = [[1,0,0,0],[0,1,0,0]],
//   Q = diag(q_pos, q_pos, q_vel, q_vel) (the paper: diag(20, 20, 1, 1)),  R = r·I,
//   S = H P̄ Hᵀ + R,  D_nds = (z − z̄)ᵀ S⁻¹ (z − z̄)  (equation (6)).
//
// The coordinates are those of one image (the tracker's reference frame, target_tracker.h);
// change_frame() carries state and covariance into another image through a homography, to
// first order (the Jacobian J of the homography at the position: v ← J v, P ← T P Tᵀ with
// T = diag(J, J)). Float only, never double; P is re-symmetrised after each step.
#pragma once
#include "base/setting_range.h"
#include "target/float/homography.h"

namespace qt {

struct TargetKalmanParams {
    float q_pos = 20.0f;  // Q's position variance per frame, px² (the paper's 20)
    float q_vel = 1.0f;   // Q's velocity variance per frame, px²/frame² (the paper's 1)
    float r = 4.0f;       // measurement variance of template matching, px² (σ = 2 px)
    float p0_vel = 4.0f;  // initial velocity variance, px²/frame² (initial position: r)
};

// TargetKalmanParams' units and accepted ranges (base/setting_range.h).
struct TargetKalmanRanges {
    SettingRange q_pos{"px^2", 0, 10000};
    SettingRange q_vel{"(px/frame)^2", 0, 1000};
    SettingRange r{"px^2", 1, 1000000, 2};  // 0.01..10000
};
inline constexpr TargetKalmanRanges kTargetKalmanRanges{};

struct Innovation {
    float nu_x = 0, nu_y = 0;  // z − H x̄, px
    float s[3] = {0, 0, 0};    // S = [[s0, s1], [s1, s2]], px²
    float det_s = 0;           // det S, px⁴
    float nds = 0;             // equation (6), dimensionless (χ² with 2 degrees of freedom)
};

// The Jacobian ∂(x', y')/∂(x, y) of h at (x, y), row-major j[0..3]; false when (x, y) maps to
// infinity.
bool homography_jacobian(const Homography& h, float x, float y, float j[4]);

class TargetKalman {
public:
    void init(float x, float y, const TargetKalmanParams& params);
    void predict();
    // Innovation of a measurement (zx, zy) against the current (predicted) state.
    Innovation innovation(float zx, float zy) const;
    // S and det S alone (no measurement): how wide the gate is.
    Innovation gate() const { return innovation(x_[0], x_[1]); }
    void update(const Innovation& in);
    // Carries the state into the image that h maps this one to. False (state unchanged) when
    // the position maps to infinity.
    bool change_frame(const Homography& h);
    // Moves the position to (x, y), px; velocity and covariance unchanged.
    void set_position(float x, float y) {
        x_[0] = x;
        x_[1] = y;
    }

    // Sets the velocity to (vx, vy), px/frame; position and covariance unchanged.
    void set_velocity(float vx, float vy) {
        x_[2] = vx;
        x_[3] = vy;
    }

    float x() const { return x_[0]; }
    float y() const { return x_[1]; }
    float vx() const { return x_[2]; }
    float vy() const { return x_[3]; }
    float p(int row, int col) const { return p_[row][col]; }

private:
    void symmetrise();

    TargetKalmanParams params_;
    float x_[4] = {0, 0, 0, 0};
    float p_[4][4] = {};
};

}  // namespace qt

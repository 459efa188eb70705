// The offset filter of the line tracker's turn model (beyond the paper; see line_tracker.h).
//
// A line turning at a constant rate ω (rad/frame) about any fixed point P keeps its distance d
// from P, so its signed distance from a fixed anchor A, ρ(t) = d + n(θ(t))·(P − A), is a
// sinusoid of angular frequency ω around d. Such a ρ satisfies ρ''' = −ω²·ρ' exactly, and a
// pure translation (ω = 0, ρ linear in t) does too. The state [ρ, ρ', ρ''] therefore moves by
//
//        | 1   sin ω / ω      (1 − cos ω) / ω² |
//   A =  | 0   cos ω          sin ω / ω        |        (Δt = 1 frame)
//        | 0   −ω·sin ω       cos ω            |
//
// which is the constant-acceleration model at ω = 0 (the acceleration the paper's equation (2)
// writes down and its matrix A leaves out) and bends that acceleration with the turn rate the
// angle filter measures. Measurement: ρ (H = [1 0 0]), variance r. Process noise: a random
// jerk per frame of variance q, Q = q·g·gᵀ with g = [1/6, 1/2, 1]ᵀ.
//
// Formats and bounds:
// | quantity      | unit            | format                      | range                      |
// |---------------|-----------------|-----------------------------|----------------------------|
// | ρ             | px              | int64, 32 fraction bits     | ±2^15; saturates (1)       |
// | ρ'            | px/frame        | int64, 32 fraction bits     | ±2^15; saturates           |
// | ρ''           | px/frame²       | int64, 32 fraction bits     | ±2^15; saturates           |
// | P (6 numbers) | px²/frame^k     | int64, 32 fraction bits     | diagonal [0, 2^28] (2)     |
// | A entries     | 1               | q2_30                       | |a| <= 1 (3)               |
// | ω             | °/frame         | q16_16 in, rad q2_30 inside | ±45                        |
// | q, r          | px²/frame⁶, px² | q16_16 (params)             | q [0, 1024], r [1/16, 1024] |
// (1) and TurnKalmanFlags::state_saturated is set; (2) |Pij| <= √(Pii·Pjj) once clamped; (3) ω is
// clamped to ±kMaxTurnDeg.
// Every product is formed in 128 bits (mul_shr_round) and rounded half away from zero; the
// transition coefficients come from Taylor series in ω² (no division, no float), truncation
// error below 2^-33 at |ω| = 45°. Saturation sets a sticky flag: re-initialise the track.
//
// RAM: sizeof(TurnKalman) == 80 bytes.
#pragma once
#include <stdint.h>

#include "base/fixed.h"

namespace qt {

// Flag bits of TurnKalman::flags().
struct TurnKalmanFlags {
    static constexpr uint8_t covariance_saturated = 1;  // a variance hit the ceiling
    static constexpr uint8_t state_saturated = 2;       // ρ, ρ' or ρ'' hit ±2^15
};

// The transition coefficients of A for one turn rate, q2_30.
struct TurnTransition {
    q2_30 sinc;     // sin ω / ω
    q2_30 one_cos;  // (1 − cos ω) / ω²
    q2_30 cos;      // cos ω
    q2_30 w_sin;    // ω·sin ω
};

// ω in degrees per frame (clamped to ±kMaxTurnDeg) -> A's coefficients.
constexpr int kMaxTurnDeg = 45;
TurnTransition turn_transition(q16_16 omega_deg);

class TurnKalman {
public:
    static constexpr int kFrac = 32;  // fraction bits of state and covariance
    static constexpr int64_t kCovCeiling = static_cast<int64_t>(1) << (28 + kFrac);

    // ρ = rho, ρ' = ρ'' = 0, P = diag(p0_pos, p0_rate, p0_accel) (each clamped to [0, 16384]).
    void init(q16_16 rho, q16_16 p0_pos, q16_16 p0_rate, q16_16 p0_accel);
    // X = A X, P = A P Aᵀ + q·g·gᵀ for turn rate omega_deg (°/frame).
    void predict(q16_16 omega_deg, q16_16 q);
    // Measurement z = ρ (px) with variance r (px², clamped to [1/16, 1024]).
    void update(q16_16 z, q16_16 r);

    q16_16 rho() const;                          // px, rounded half away
    const int64_t* state() const { return x_; }  // ρ, ρ', ρ'', 32 fraction bits
    const int64_t* cov() const { return p_; }    // P00 P01 P02 P11 P12 P22, 32 fraction bits
    uint8_t flags() const { return flags_; }     // TurnKalmanFlags bits, sticky until init()

private:
    int64_t x_[3] = {0, 0, 0};
    int64_t p_[6] = {0, 0, 0, 0, 0, 0};
    uint8_t flags_ = 0;
};

}  // namespace qt

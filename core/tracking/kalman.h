// The Kalman filter of the 3KF line tracker, in fixed point: the Quadrangle Detection paper §2.6,
// equations (3)–(5). It tracks the closest point C = (x, y) of a line (pixels) with
//
//   X = [x, ẋ, y, ẏ]ᵀ (px, px/frame),  Z = [x, y]ᵀ (px),  Δt = 1 frame,
//   A = [[1,Δt,0,0],[0,1,0,0],[0,0,1,Δt],[0,0,0,1]],  H = [[1,0,0,0],[0,0,1,0]],
//   Q = q·[[Δt⁴/4, Δt³/2, 0, 0], [Δt³/2, Δt², 0, 0], [0, 0, Δt⁴/4, Δt³/2], [0, 0, Δt³/2, Δt²]],
//   R = r·I  (the paper: q = 1, r = 0.5).
//
// Two independent axes. A, H, Q and R are block diagonal in ([x, ẋ], [y, ẏ]) and P0 is too, so
// the cross-axis terms of P start at zero and stay exactly zero through every predict
// (A P Aᵀ + Q keeps the blocks apart) and every update (K = P Hᵀ S⁻¹ with S diagonal). The 4×4
// filter is therefore two identical 2-state filters on [x, ẋ] and [y, ẏ], each with a 2×2
// symmetric covariance stored as three numbers and a scalar innovation covariance S = Ppp + r:
// half the arithmetic and RAM of the 4×4 form, and mathematically the same filter (the test
// runs a full 4×4 double-precision filter beside it). Per axis, with P = [[a, b], [b, c]]:
//
//   predict:  x ← x + ẋ                        a ← a + 2b + c + q/4
//             ẋ ← ẋ                            b ← b + c + q/2
//                                              c ← c + q
//   update:   S = a + r,  K = [a/S, b/S]ᵀ      (one reciprocal 1/S per axis, S >= r > 0)
//             ν = z − x,  x ← x + K₁ν,  ẋ ← ẋ + K₂ν
//             a ← a·r/S,  b ← b·r/S,  c ← c − b·K₂     (= (I − K H) P, exactly)
//
// Formats and bounds (the arithmetic behind each bound is beside the code in kalman.cpp):
//
// | quantity          | unit       | format                  | range                          |
// |-------------------|------------|-------------------------|--------------------------------|
// | x, y              | px         | q16_16                  | ±32768 (measurements ±16384    |
// |                   |            |                         | expected); saturates (1)       |
// | ẋ, ẏ              | px/frame   | q16_16                  | ±32768; saturates (1)          |
// | P: a = Ppp        | px²        | int64, 32 fraction bits | [0, kCovCeiling = 2^28]        |
// | P: b = Ppv        | px²/frame  | int64, 32 fraction bits | [−2^28, 2^28], |b| <= √(a·c)   |
// | P: c = Pvv        | px²/frame² | int64, 32 fraction bits | [0, 2^28]                      |
// | r (R = r·I)       | px²        | q16_16 (param)          | [1/16, 1024]                   |
// | q (Q scale)       | px²/frame⁴ | q16_16 (param)          | [0, 1024]                      |
// | S = a + r         | px²        | int64, 32 fraction bits | [1/16, 2^28 + 1024]            |
// | 1/S               | 1/px²      | (2)                     | relative error <= 2^−62        |
// | K₁ = a/S, and r/S | 1          | int64, 59 fraction bits | [0, 1]; r/S >= 2^-33           |
// | K₂ = b/S          | 1/frame    | int64, 44 fraction bits | |K₂| <= √(c/r)/2 <= 2^15       |
// | ν = z − x         | px         | int64, 16 fraction bits | ±65536                         |
// (1) and the flag state_saturated is set; (2) m·2^−(L+61), m ∈ [2^61, 2^62], L = the bit length
// of S's raw value.
//
// Rounding: predict is exact (integer additions; q/4 and q/2 are exact because q arrives with 16
// fraction bits and P has 32) apart from saturation. In update the reciprocal's mantissa rounds
// half up (positive); every product rounds half away from zero to its destination format. No
// signed overflow anywhere: all products are formed in 128 bits from 32-bit limbs
// (mul_shr_round, wide_mul.h) and saturate when narrowed to 64 bits.
//
// Saturation. With no measurement the covariance of constant-velocity prediction grows like
// a(n) = a0 + 2·b0·n + c0·n² + q·(n³/3 − n/12): from the default P0 (q = 1) a is 1.33·10^6 px²
// (σ ≈ 1150 px) after 100 frames, far below the ceiling; it reaches kCovCeiling = 2^28 px²
// (σ = 16384 px, the whole position range: "anywhere") after about 840 frames (about 930 from
// the steady state). There a, b and c are clamped to the ceiling and, to keep P positive
// semi-definite so that a later update stays meaningful, |b| is held at most
// ⌊√a⌋·⌊√c⌋ <= √(a·c); flag covariance_saturated is set and stays set until init(). After 1000
// frames the flag is set and a = 2^28; after 10^6 frames a = 2^28, c = c0 + q·10^6 (c reaches the
// ceiling only after ~2.7·10^8/q frames), b ≈ √(a·c), and a non-zero velocity has driven the
// position to ±32768 (flag state_saturated). Nothing wraps. Once a flag is set the numbers are
// bounds, not the true covariance: the caller should re-initialise from the next measurement.
//
// RAM: sizeof(PointKalman) == 80 bytes (two axes of 32 bytes, r and q, flags; 8-byte aligned on
// x86-64, AArch64 and Cortex-M). No heap, no float.
#pragma once
#include <stdint.h>

#include "base/fixed.h"

namespace qt {

struct KalmanParams {
    // Measurement noise variance per axis, R = r·I, px². The paper's 0.5. Range [1/16, 1024].
    q16_16 r = q16_16::from_ratio(1, 2);
    // Process noise scale: Q = q·[[Δt⁴/4, Δt³/2], [Δt³/2, Δt²]] per axis, i.e. q is the variance
    // of a per-frame random acceleration, px²/frame⁴. The paper's Q is q = 1. Range [0, 1024].
    q16_16 q = q16_16::from_int(1);
    // Initial position variance, px². Default r: the first measurement is the only information
    // about the position, so its variance is R's. Range [0, 16384].
    q16_16 p0_pos = q16_16::from_ratio(1, 2);
    // Initial velocity variance, px²/frame². Nothing is known about the velocity at the first
    // sighting; 100 (σ = 10 px/frame) covers the few px/frame at which lines move in the paper's
    // experiments (1–3 px/frame) and in hand-held use with a wide margin, yet lets the second
    // measurement set the velocity almost entirely (K₂ = 134/135 on the first update).
    // Range [0, 16384].
    q16_16 p0_vel = q16_16::from_int(100);
};

// One axis of the filter: [position, velocity] and its 2×2 symmetric covariance.
struct KalmanAxis {
    static constexpr int cov_frac = 32;  // fraction bits of pp, pv, vv
    q16_16 pos;                          // px
    q16_16 vel;                          // px/frame
    int64_t pp;                          // Ppp, px², 32 fraction bits
    int64_t pv;                          // Ppv, px²/frame, 32 fraction bits
    int64_t vv;                          // Pvv, px²/frame², 32 fraction bits
};

// The gain the next update() will apply on one axis, each within one LSB of its exact value.
struct KalmanGain {
    static constexpr int pos_frac = 59;  // fraction bits of k_pos
    static constexpr int vel_frac = 44;  // fraction bits of k_vel
    int64_t k_pos;                       // K₁ = Ppp/S, dimensionless, [0, 1] (raw <= 2^59)
    int64_t k_vel;                       // K₂ = Ppv/S, 1/frame, |K₂| <= 2^15 (raw <= 2^59)
};

// One axis on its own, for filters built from it (the line tracker's angle, turn model).
// Position pos, velocity 0, P = diag(p0_pos, p0_vel); q and r as in KalmanParams, clamped into
// their ranges. predict and update return KalmanFlags bits.
KalmanAxis kalman_axis_init(q16_16 pos, q16_16 p0_pos, q16_16 p0_vel);
uint8_t kalman_axis_predict(KalmanAxis& ax, q16_16 q);
uint8_t kalman_axis_update(KalmanAxis& ax, q16_16 z, q16_16 r);

// Flag bits of PointKalman::flags().
struct KalmanFlags {
    static constexpr uint8_t covariance_saturated = 1;  // P hit kCovCeiling: re-initialise
    static constexpr uint8_t state_saturated = 2;  // a position or velocity hit the q16_16 range
};

// The paper's filter on one point (§2.6), x and y axes independent (see the top of the file).
class PointKalman {
public:
    static constexpr int64_t kCovCeiling = static_cast<int64_t>(1) << (28 + KalmanAxis::cov_frac);

    // Position (x, y) = first measurement, velocity 0, P = diag(p0_pos, p0_vel) per axis, flags
    // cleared. Parameters outside their ranges are clamped into them; returns false if any was.
    bool init(q16_16 x, q16_16 y, const KalmanParams& params = KalmanParams{});
    // X = A X, P = A P Aᵀ + Q: one frame without a measurement (or before update()).
    void predict();
    // The standard update with measurement (zx, zy), px.
    void update(q16_16 zx, q16_16 zy);

    q16_16 x() const { return x_.pos; }   // px
    q16_16 y() const { return y_.pos; }   // px
    q16_16 vx() const { return x_.vel; }  // px/frame
    q16_16 vy() const { return y_.vel; }  // px/frame
    const KalmanAxis& axis_x() const { return x_; }
    const KalmanAxis& axis_y() const { return y_; }
    KalmanGain gain_x() const;  // the gains the next update() uses on x
    KalmanGain gain_y() const;

    uint8_t flags() const { return flags_; }  // KalmanFlags bits, sticky until init()
    bool saturated() const { return flags_ != 0; }

private:
    // Before the first init(): at the origin, at rest, P = 0, the default parameters.
    KalmanAxis x_{q16_16{0}, q16_16{0}, 0, 0, 0};
    KalmanAxis y_{q16_16{0}, q16_16{0}, 0, 0, 0};
    q16_16 r_ = q16_16::from_ratio(1, 2);  // px²
    q16_16 q_ = q16_16::from_int(1);       // px²/frame⁴
    uint8_t flags_ = 0;
};

}  // namespace qt

#include "tracking/turn_kalman.h"

#include "base/isqrt.h"
#include "base/wide_mul.h"

namespace qt {

namespace {

constexpr int kFrac = TurnKalman::kFrac;             // 32
constexpr int kToState = kFrac - q16_16::frac_bits;  // q16_16 raw -> state / covariance raw
constexpr int kGainFrac = 44;                        // K₁, K₂: |K| <= 2^15 (see update)
constexpr int kUnitGainFrac = 59;                    // K₀ and r/S, both in [0, 1]
constexpr int64_t kCeil = TurnKalman::kCovCeiling;   // 2^28 px² = 2^60 raw
constexpr int64_t kStateMax = pow2(15 + kFrac);      // ±2^15 px, px/frame, px/frame²
constexpr int64_t kOne30 = pow2(30);                 // 1.0 in q2_30
// π/180 with 46 fraction bits: round(2^46·π/180) = 1228166276394 (relative error 4·10^-13).
constexpr int64_t kRadPerDeg46 = 1228166276394;
constexpr int64_t kRMin = q16_16::one_raw / 16, kRMax = 1024 * q16_16::one_raw;
constexpr int64_t kQMax = 1024 * q16_16::one_raw, kP0Max = 16384 * q16_16::one_raw;

static_assert(sizeof(TurnKalman) <= 80, "RAM as documented");
// A P Aᵀ: every row of |A| sums to at most 1 + 1 + 1/2, so with |Pij| <= 2^60 the products are
// below 2.5²·2^60 < 2^63, and adding Q (<= 2^42) stays in range.
static_assert(pow2(60) / 4 * 25 + (kQMax << kToState) < INT64_MAX, "A P A^T fits int64");
static_assert(kCeil + (kRMax << kToState) < pow2(62), "S range of reciprocal()");

int64_t mul30(int64_t a, int64_t b) { return mul_shr_round(a, b, 30); }

// 1 − w²·s/d in q2_30, the Horner step of the series below.
int64_t horner_step(int64_t w2, int64_t s, int64_t d) {
    return kOne30 - div_round_half_away(mul30(w2, s), d);
}

// x + d clamped to ±kStateMax; sets `sat` when it had to. d is clamped first so the sum
// cannot overflow.
int64_t add_state(int64_t x, int64_t d, bool& sat) {
    const int64_t sum = x + clamp64(d, -pow2(62), pow2(62) - kStateMax);
    if (sum > kStateMax || sum < -kStateMax) sat = true;
    return clamp64(sum, -kStateMax, kStateMax);
}

int64_t to_cov(int64_t q16_raw) { return q16_raw * pow2(kToState); }

}  // namespace

TurnTransition turn_transition(q16_16 omega_deg) {
    const int64_t deg =
        clamp64(omega_deg.raw, -kMaxTurnDeg * q16_16::one_raw, kMaxTurnDeg * q16_16::one_raw);
    // |deg| <= 45·2^16 raw: the product stays below 2^62. Radians, q2_30, |w| <= 0.786.
    const int64_t w = shr_round_half_away(deg * kRadPerDeg46, 32);
    const int64_t w2 = mul30(w, w);  // [0, 0.62]
    // sin w / w = 1 − w²/(2·3)·(1 − w²/(4·5)·(1 − w²/(6·7)·(1 − w²/(8·9)·(1 − w²/(10·11)))));
    // the first term left out, w^12/13!, is below 10^-11 at |w| = π/4.
    static constexpr int64_t kSincDen[5] = {110, 72, 42, 20, 6};
    int64_t sinc = kOne30;
    for (const int64_t d : kSincDen) sinc = horner_step(w2, sinc, d);
    // (1 − cos w)/w² = 1/2·(1 − w²/(3·4)·(1 − w²/(5·6)·(1 − w²/(7·8)·(1 − w²/(9·10)·
    // (1 − w²/(11·12)))))); first term left out w^12/14! < 10^-12.
    static constexpr int64_t kOneCosDen[5] = {132, 90, 56, 30, 12};
    int64_t oc = kOne30;
    for (const int64_t d : kOneCosDen) oc = horner_step(w2, oc, d);
    oc = shr_round_half_away(oc, 1);
    TurnTransition t;
    t.sinc = q2_30::from_raw(sinc);
    t.one_cos = q2_30::from_raw(oc);
    t.cos = q2_30::from_raw(kOne30 - mul30(w2, oc));
    t.w_sin = q2_30::from_raw(mul30(w2, sinc));
    return t;
}

void TurnKalman::init(q16_16 rho, q16_16 p0_pos, q16_16 p0_rate, q16_16 p0_accel) {
    x_[0] = to_cov(rho.raw);
    x_[1] = x_[2] = 0;
    p_[0] = to_cov(clamp64(p0_pos.raw, 0, kP0Max));
    p_[3] = to_cov(clamp64(p0_rate.raw, 0, kP0Max));
    p_[5] = to_cov(clamp64(p0_accel.raw, 0, kP0Max));
    p_[1] = p_[2] = p_[4] = 0;
    flags_ = 0;
}

void TurnKalman::predict(q16_16 omega_deg, q16_16 q) {
    const TurnTransition t = turn_transition(omega_deg);
    const int64_t a[3][3] = {{kOne30, t.sinc.raw, t.one_cos.raw},
                             {0, t.cos.raw, t.sinc.raw},
                             {0, -static_cast<int64_t>(t.w_sin.raw), t.cos.raw}};
    bool state_sat = false;
    int64_t x[3];
    for (int i = 0; i < 3; ++i) {
        int64_t sum = 0;  // |a| row sums <= 2.5, |x| <= 2^47: no overflow
        for (int k = 0; k < 3; ++k) sum += mul30(a[i][k], x_[k]);
        x[i] = add_state(0, sum, state_sat);
    }
    for (int i = 0; i < 3; ++i) x_[i] = x[i];

    const int64_t p[3][3] = {{p_[0], p_[1], p_[2]}, {p_[1], p_[3], p_[4]}, {p_[2], p_[4], p_[5]}};
    int64_t m[3][3];  // A·P
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int64_t sum = 0;
            for (int k = 0; k < 3; ++k) sum += mul30(a[i][k], p[k][j]);
            m[i][j] = sum;
        }
    const int64_t q_cov = to_cov(clamp64(q.raw, 0, kQMax));
    // Q = q·g·gᵀ, g = [1/6, 1/2, 1]: entries q/36, q/12, q/6, q/4, q/2, q, rounded half away.
    const int64_t qg[3][3] = {{div_round_half_away(q_cov, 36), div_round_half_away(q_cov, 12),
                               div_round_half_away(q_cov, 6)},
                              {0, q_cov / 4, q_cov / 2},
                              {0, 0, q_cov}};
    int64_t out[3][3];  // A·P·Aᵀ + Q, upper triangle
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            int64_t sum = qg[i][j];
            for (int k = 0; k < 3; ++k) sum += mul30(m[i][k], a[j][k]);
            out[i][j] = sum;
        }
    const bool cov_sat = out[0][0] > kCeil || out[1][1] > kCeil || out[2][2] > kCeil;
    p_[0] = clamp64(out[0][0], 0, kCeil);
    p_[3] = clamp64(out[1][1], 0, kCeil);
    p_[5] = clamp64(out[2][2], 0, kCeil);
    p_[1] = clamp64(out[0][1], -kCeil, kCeil);
    p_[2] = clamp64(out[0][2], -kCeil, kCeil);
    p_[4] = clamp64(out[1][2], -kCeil, kCeil);
    if (cov_sat) {
        // Keep P positive semi-definite pairwise once a variance sits at the ceiling (as in
        // kalman.cpp): |Pij| <= ⌊√Pii⌋·⌊√Pjj⌋.
        const int64_t s0 = static_cast<int64_t>(isqrt64(static_cast<uint64_t>(p_[0])));
        const int64_t s1 = static_cast<int64_t>(isqrt64(static_cast<uint64_t>(p_[3])));
        const int64_t s2 = static_cast<int64_t>(isqrt64(static_cast<uint64_t>(p_[5])));
        p_[1] = clamp64(p_[1], -s0 * s1, s0 * s1);
        p_[2] = clamp64(p_[2], -s0 * s2, s0 * s2);
        p_[4] = clamp64(p_[4], -s1 * s2, s1 * s2);
    }
    flags_ = static_cast<uint8_t>(flags_ | (cov_sat ? TurnKalmanFlags::covariance_saturated : 0) |
                                  (state_sat ? TurnKalmanFlags::state_saturated : 0));
}

void TurnKalman::update(q16_16 z, q16_16 r) {
    const int64_t r_cov = to_cov(clamp64(r.raw, kRMin, kRMax));
    const Reciprocal inv = reciprocal(p_[0] + r_cov);  // S ∈ [2^28, 2^62) raw
    // K₀ = P00/S ∈ [0, 1] and r/S, 59 fraction bits; K₁ = P01/S, K₂ = P02/S with
    // |K| <= √(Pii)/(2√r) <= 2^14/(2·2^-2) = 2^15 while P is positive semi-definite: 44
    // fraction bits keep them below 2^59 (and mul_shr_round saturates if they were not).
    const int64_t k0 = clamp64(inv.ratio(p_[0], kUnitGainFrac), 0, pow2(kUnitGainFrac));
    const int64_t k1 = inv.ratio(p_[1], kGainFrac);
    const int64_t k2 = inv.ratio(p_[2], kGainFrac);
    const int64_t g = clamp64(inv.ratio(r_cov, kUnitGainFrac), 0, pow2(kUnitGainFrac));
    const int64_t nu = to_cov(z.raw) - x_[0];  // |ν| <= 2^16 px: below 2^49 raw
    bool state_sat = false;
    x_[0] = add_state(x_[0], mul_shr_round(k0, nu, kUnitGainFrac), state_sat);
    x_[1] = add_state(x_[1], mul_shr_round(k1, nu, kGainFrac), state_sat);
    x_[2] = add_state(x_[2], mul_shr_round(k2, nu, kGainFrac), state_sat);
    // (I − K H) P with the old first row: row 0 scales by r/S (= 1 − K₀, kept in relative
    // precision), the rest subtract K_i·P0j; the variances are clamped at 0 against rounding.
    const int64_t p01 = p_[1], p02 = p_[2];
    p_[0] = mul_shr_round(p_[0], g, kUnitGainFrac);
    p_[1] = mul_shr_round(p01, g, kUnitGainFrac);
    p_[2] = mul_shr_round(p02, g, kUnitGainFrac);
    p_[3] = clamp64(p_[3] - mul_shr_round(k1, p01, kGainFrac), 0, kCeil);
    p_[4] = clamp64(p_[4] - mul_shr_round(k1, p02, kGainFrac), -kCeil, kCeil);
    p_[5] = clamp64(p_[5] - mul_shr_round(k2, p02, kGainFrac), 0, kCeil);
    if (state_sat) flags_ = static_cast<uint8_t>(flags_ | TurnKalmanFlags::state_saturated);
}

q16_16 TurnKalman::rho() const { return q16_16::from_raw(shr_round_half_away(x_[0], kToState)); }

}  // namespace qt

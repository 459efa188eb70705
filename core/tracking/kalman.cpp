#include "tracking/kalman.h"

#include "base/isqrt.h"
#include "base/wide_mul.h"

namespace qt {

namespace {

constexpr int kCovFrac = KalmanAxis::cov_frac;        // 32
constexpr int kPosGainFrac = KalmanGain::pos_frac;    // 59: K₁ and r/S, both in [0, 1]
constexpr int kVelGainFrac = KalmanGain::vel_frac;    // 44: K₂, |K₂| <= 2^15
constexpr int kToCov = kCovFrac - q16_16::frac_bits;  // q16_16 raw -> covariance raw
constexpr int64_t kCeil = PointKalman::kCovCeiling;   // 2^60 raw = 2^28 px²
constexpr int64_t kPosGainOne = pow2(kPosGainFrac);   // 1.0 in K₁ raw

// Parameter ranges, q16_16 raw.
constexpr int64_t kRMin = q16_16::one_raw / 16, kRMax = 1024 * q16_16::one_raw;
constexpr int64_t kQMax = 1024 * q16_16::one_raw;
constexpr int64_t kP0Max = 16384 * q16_16::one_raw;

// Bounds behind the arithmetic (raw units, 32 fraction bits for P):
// predict sums a + 2b + c + q/4 with |a|, |b|, |c| <= 2^60 and q <= 2^10·2^32:
static_assert(4 * kCeil + (kQMax << kToCov) / 4 < INT64_MAX, "predict sums fit int64");
// Initial variances stay below the ceiling.
static_assert((kP0Max << kToCov) <= kCeil, "P0 below the ceiling");
// RAM: two 32-byte axes, r and q (4 bytes each), the flags byte, padding to 8 bytes.
static_assert(sizeof(KalmanAxis) == 32, "axis layout");
static_assert(sizeof(PointKalman) <= 80, "RAM per filter as documented");

// S = a + r ∈ [2^28, 2^60 + 2^42]: the smallest is r's minimum, 2^-4 px² = 2^28 raw (never 0,
// len >= 29); the largest stays below 2^62 (len <= 62, and the restoring division's d < 2^63).
static_assert((kRMin << kToCov) == pow2(28) && kCeil + (kRMax << kToCov) < pow2(62),
              "S range of reciprocal()");

KalmanGain gain_of(const KalmanAxis& ax, const Reciprocal& inv) {
    // K₁ = a/S ∈ [0, 1), 59 fraction bits (raw <= 2^59; clamped in case rounding ever put a/S
    // a hair above 1 when r << a).
    // K₂ = b/S, 44 fraction bits: |K₂| <= √(a·c)/(a + r) <= √c/(2√r) <= 2^14/(2·2^-2) = 2^15
    // (raw <= 2^59) while P is positive semi-definite (b² <= a·c; kept so after saturation).
    // The 128-bit product and its saturation make this safe even if it were not.
    return KalmanGain{clamp64(inv.ratio(ax.pp, kPosGainFrac), 0, kPosGainOne),
                      inv.ratio(ax.pv, kVelGainFrac)};
}

// v + d (raw q16_16), saturated; sets `sat` if it had to.
q16_16 add_sat_flag(q16_16 v, int64_t d, bool& sat) {
    const int64_t sum = static_cast<int64_t>(v.raw) + clamp64(d, -pow2(40), pow2(40));
    if (sum < int_limits<int32_t>::lo || sum > int_limits<int32_t>::hi) sat = true;
    return q16_16::from_raw(sum);
}

// One axis, one frame: x ← x + ẋ, P ← A P Aᵀ + Q. Exact up to saturation. Returns the flags.
uint8_t predict_axis(KalmanAxis& ax, int64_t q_cov) {
    bool state_sat = false;
    ax.pos = add_sat_flag(ax.pos, ax.vel.raw, state_sat);  // Δt = 1 frame
    // |a|, |b|, |c| <= 2^60 on entry, q <= 2^42: every sum < 2^63 (static_assert above).
    // q/4 and q/2 are exact: q_cov = q16_16 raw · 2^16.
    const int64_t a = ax.pp + 2 * ax.pv + ax.vv + q_cov / 4;
    const int64_t b = ax.pv + ax.vv + q_cov / 2;
    const int64_t c = ax.vv + q_cov;
    // a and c are >= 0 in exact arithmetic (a = [1 1] P [1 1]ᵀ + q/4); the clamp at 0 only
    // absorbs rounding of earlier updates and does not count as saturation.
    ax.pp = clamp64(a, 0, kCeil);
    ax.pv = clamp64(b, -kCeil, kCeil);
    ax.vv = clamp64(c, 0, kCeil);
    const bool cov_sat = a > kCeil || b > kCeil || b < -kCeil || c > kCeil;
    if (cov_sat) {
        // Clamping a alone would let b² outgrow a·c (b ~ q·n²/2 against a fixed a and
        // c ~ q·n); hold |b| <= ⌊√a⌋·⌊√c⌋ <= √(a·c) <= 2^60 so that P stays positive
        // semi-definite. Applied only on this axis and only while it sits at the ceiling (once
        // a is there, every further predict reaches it again until an update): normal
        // operation stays exact.
        const int64_t bmax = static_cast<int64_t>(isqrt64(static_cast<uint64_t>(ax.pp))) *
                             static_cast<int64_t>(isqrt64(static_cast<uint64_t>(ax.vv)));
        ax.pv = clamp64(ax.pv, -bmax, bmax);
    }
    return static_cast<uint8_t>((cov_sat ? KalmanFlags::covariance_saturated : 0) |
                                (state_sat ? KalmanFlags::state_saturated : 0));
}

// One axis: the measurement update with z (px). Returns the flags.
uint8_t update_axis(KalmanAxis& ax, q16_16 z, int64_t r_cov) {
    const Reciprocal inv = reciprocal(ax.pp + r_cov);  // S = a + r ∈ [2^28, 2^62] raw, > 0
    const KalmanGain k = gain_of(ax, inv);
    // r/S ∈ (0, 1], 59 fraction bits, rounded half away. Computed from r rather than as 1 − K₁
    // so that it keeps its relative precision when S >> r: r/S >= 2^-4/(2^28 + 2^10) > 2^-33,
    // so g >= 2^26 raw, relative rounding error <= 2^-27 even at the ceiling.
    const int64_t g = clamp64(inv.ratio(r_cov, kPosGainFrac), 0, kPosGainOne);
    // Innovation ν = z − x, 16 fraction bits, |ν| <= 2^16 px: exact in int64.
    const int64_t nu = static_cast<int64_t>(z.raw) - ax.pos.raw;
    bool state_sat = false;
    // x + K₁ν lies between x and z: no saturation possible. The products have 59 + 16 and
    // 44 + 16 fraction bits (< 2^59·2^33 = 2^92, exact in 128 bits), rounded half away to 16;
    // |K₂ν| <= 2^15·2^16 px/frame before the q16_16 clamp.
    ax.pos = add_sat_flag(ax.pos, mul_shr_round(k.k_pos, nu, kPosGainFrac), state_sat);
    ax.vel = add_sat_flag(ax.vel, mul_shr_round(k.k_vel, nu, kVelGainFrac), state_sat);
    // (I − K H) P with the old b on the right: a·r/S <= r, |b·r/S| <= |b|, and
    // c − b·K₂ = c − b²/S ∈ [0, c] (b·K₂ >= 0). Products < 2^60·2^59 = 2^119, each rounded half
    // away to 32 fraction bits; the clamp at 0 only absorbs that rounding.
    const int64_t b_old = ax.pv;
    ax.pp = mul_shr_round(ax.pp, g, kPosGainFrac);
    ax.pv = mul_shr_round(b_old, g, kPosGainFrac);
    ax.vv = clamp64(ax.vv - mul_shr_round(b_old, k.k_vel, kVelGainFrac), 0, kCeil);
    return state_sat ? KalmanFlags::state_saturated : 0;
}

int64_t to_cov(q16_16 v) { return static_cast<int64_t>(v.raw) * pow2(kToCov); }

}  // namespace

bool PointKalman::init(q16_16 x, q16_16 y, const KalmanParams& params) {
    const int64_t r = clamp64(params.r.raw, kRMin, kRMax);
    const int64_t q = clamp64(params.q.raw, 0, kQMax);
    const int64_t p0p = clamp64(params.p0_pos.raw, 0, kP0Max);
    const int64_t p0v = clamp64(params.p0_vel.raw, 0, kP0Max);
    r_ = q16_16::from_raw(r);
    q_ = q16_16::from_raw(q);
    const int64_t pp = to_cov(q16_16::from_raw(p0p)), vv = to_cov(q16_16::from_raw(p0v));
    x_ = KalmanAxis{x, q16_16{0}, pp, 0, vv};
    y_ = KalmanAxis{y, q16_16{0}, pp, 0, vv};
    flags_ = 0;
    return r == params.r.raw && q == params.q.raw && p0p == params.p0_pos.raw &&
           p0v == params.p0_vel.raw;
}

void PointKalman::predict() {
    const int64_t q = to_cov(q_);
    const uint8_t fx = predict_axis(x_, q);
    const uint8_t fy = predict_axis(y_, q);
    flags_ = static_cast<uint8_t>(flags_ | fx | fy);
}

void PointKalman::update(q16_16 zx, q16_16 zy) {
    const int64_t r = to_cov(r_);
    const uint8_t fx = update_axis(x_, zx, r);
    const uint8_t fy = update_axis(y_, zy, r);
    flags_ = static_cast<uint8_t>(flags_ | fx | fy);
}

KalmanAxis kalman_axis_init(q16_16 pos, q16_16 p0_pos, q16_16 p0_vel) {
    return KalmanAxis{pos, q16_16{0}, to_cov(q16_16::from_raw(clamp64(p0_pos.raw, 0, kP0Max))), 0,
                      to_cov(q16_16::from_raw(clamp64(p0_vel.raw, 0, kP0Max)))};
}

uint8_t kalman_axis_predict(KalmanAxis& ax, q16_16 q) {
    return predict_axis(ax, to_cov(q16_16::from_raw(clamp64(q.raw, 0, kQMax))));
}

uint8_t kalman_axis_update(KalmanAxis& ax, q16_16 z, q16_16 r) {
    return update_axis(ax, z, to_cov(q16_16::from_raw(clamp64(r.raw, kRMin, kRMax))));
}

KalmanGain PointKalman::gain_x() const { return gain_of(x_, reciprocal(x_.pp + to_cov(r_))); }
KalmanGain PointKalman::gain_y() const { return gain_of(y_, reciprocal(y_.pp + to_cov(r_))); }

}  // namespace qt

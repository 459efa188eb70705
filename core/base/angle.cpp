#include "base/angle.h"

namespace qt {

namespace {

// atan(2^-i) in binary-angle units: round(atan(2^-i) / (2π) · 2^32), i = 0..29.
// tests/base/test_angle.cpp bounds atan2_angle and sin_cos against std::atan2, std::sin, std::cos.
constexpr uint32_t kAtanTable[30] = {536870912, 316933406, 167458907, 85004756, 42667331, 21354465,
                                     10679838,  5340245,   2670163,   1335087,  667544,   333772,
                                     166886,    83443,     41722,     20861,    10430,    5215,
                                     2608,      1304,      652,       326,      163,      81,
                                     41,        20,        10,        5,        3,        1};
constexpr int kIterations = 30;

// Product of 1/sqrt(1 + 2^-2i) over the 30 iterations, q2_30: 0.60725293500888 · 2^30.
constexpr int32_t kCordicGainInverse = 652032874;

}  // namespace

angle_t angle_from_deg(q16_16 deg) {
    const int64_t units = div_round_half_away(static_cast<int64_t>(deg.raw) * pow2(16), 360);
    return static_cast<angle_t>(static_cast<uint64_t>(units) & 0xFFFFFFFFu);
}

q16_16 angle_to_deg(angle_t a) {
    const int64_t s =
        a < kAngleHalfTurn ? static_cast<int64_t>(a) : static_cast<int64_t>(a) - pow2(32);
    return q16_16::from_raw(shr_round_half_away(s * 360, 16));
}

angle_t atan2_angle(int32_t y, int32_t x) {
    int64_t X = x, Y = y;
    // The axes exactly (CORDIC alone would leave a residue of a few units there).
    if (Y == 0) return X < 0 ? kAngleHalfTurn : 0;
    if (X == 0) return Y > 0 ? kAngleQuarterTurn : 3u * kAngleQuarterTurn;
    angle_t angle = 0;
    if (X < 0) {  // rotate by 180° into the right half plane, where CORDIC converges
        X = -X;
        Y = -Y;
        angle = kAngleHalfTurn;
    }
    // Normalise max(|X|, |Y|) into [2^28, 2^29): enough bits for precision, and the CORDIC
    // growth (×1.647, ×√2 at most) keeps every iterate below 2^31.
    // k halvings (each truncating toward zero, as one division by 2^k does) or doublings, the
    // count from the top bit of m (one CLZ).
    const uint64_t m = static_cast<uint64_t>(X > abs64(Y) ? X : abs64(Y));
    const int top = 63 - __builtin_clzll(m);  // m >= 1: both are nonzero here
    if (top >= 29) {
        const int k = top - 28;
        X >>= k;  // X > 0
        Y = shr_toward_zero(Y, k);
    } else if (top < 28) {
        const int k = 28 - top;
        X *= pow2(k);
        Y *= pow2(k);
    }
    int32_t xi = static_cast<int32_t>(X), yi = static_cast<int32_t>(Y);
#pragma GCC unroll 30  // shifts and table entries become constants
    for (int i = 0; i < kIterations; ++i) {
        const int32_t dx = xi >> i, dy = yi >> i;
        if (yi > 0) {  // rotate clockwise by atan(2^-i)
            xi += dy;
            yi -= dx;
            angle += kAtanTable[i];
        } else {
            xi -= dy;
            yi += dx;
            angle -= kAtanTable[i];
        }
    }
    return angle;
}

SinCos sin_cos(angle_t a) {
    // Signed residual angle in (-180°, 180°], then folded into [-90°, 90°] where CORDIC
    // converges; the fold by 180° negates both results.
    int64_t z = a < kAngleHalfTurn ? static_cast<int64_t>(a) : static_cast<int64_t>(a) - pow2(32);
    bool flip = false;
    if (z > static_cast<int64_t>(kAngleQuarterTurn)) {
        z -= kAngleHalfTurn;
        flip = true;
    } else if (z < -static_cast<int64_t>(kAngleQuarterTurn)) {
        z += kAngleHalfTurn;
        flip = true;
    }
    int32_t x = kCordicGainInverse, y = 0;
    int32_t zi = static_cast<int32_t>(z);
#pragma GCC unroll 30  // as in atan2_angle
    for (int i = 0; i < kIterations; ++i) {
        const int32_t dx = x >> i, dy = y >> i;
        const int32_t step = static_cast<int32_t>(kAtanTable[i]);
        if (zi >= 0) {
            x -= dy;
            y += dx;
            zi -= step;
        } else {
            x += dy;
            y -= dx;
            zi += step;
        }
    }
    if (flip) {
        x = -x;
        y = -y;
    }
    return SinCos{q2_30{y}, q2_30{x}};
}

}  // namespace qt

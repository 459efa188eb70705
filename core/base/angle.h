// Angles as binary fractions of a turn, sines and cosines, atan2 — by CORDIC: shifts, adds and
// a 30-entry arctangent table; no float, no multiplier in the iterations.
#pragma once
#include <stdint.h>

#include "base/fixed.h"

namespace qt {

// Binary angle: 2^32 units per turn (1 unit = 360°/2^32 ≈ 8.4e-8°). Unsigned, so adding and
// subtracting angles wraps modulo one turn with no overflow to worry about.
using angle_t = uint32_t;

constexpr angle_t kAngleQuarterTurn = 1u << 30;  // 90°
constexpr angle_t kAngleHalfTurn = 1u << 31;     // 180°

// Whole degrees (any sign) to a binary angle: deg · 2^32 / 360, rounded half away from zero,
// wrapped into one turn.
constexpr angle_t angle_from_deg(int32_t deg) {
    const int64_t units = div_round_half_away(static_cast<int64_t>(deg) * pow2(32), 360);
    return static_cast<angle_t>(static_cast<uint64_t>(units) & 0xFFFFFFFFu);
}

// Degrees in q16_16 (any value in range) to a binary angle: raw · 2^16 / 360, rounded half away.
angle_t angle_from_deg(q16_16 deg);

// A binary angle as signed degrees in [-180, 180), q16_16, rounded half away from zero.
q16_16 angle_to_deg(angle_t a);

// Direction of the vector (x, y), measured from +x towards +y; (0, 0) gives 0 and the four
// axis directions are exact. Absolute error below 2e-6° for inputs of any magnitude (they are
// normalised to 2^28..2^29 before the iterations); tests/base/test_angle.cpp holds the bound.
angle_t atan2_angle(int32_t y, int32_t x);

struct SinCos {
    q2_30 sin;
    q2_30 cos;
};

// sin and cos of a, in q2_30 (1.0 = 2^30), absolute error below 2^-25 (tests/base/test_angle.cpp).
SinCos sin_cos(angle_t a);

}  // namespace qt

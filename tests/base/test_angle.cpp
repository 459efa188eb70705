// CORDIC angles against std::atan2, std::sin and std::cos.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "base/angle.h"
#include "base/prng.h"

using namespace qt;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kUnitsPerDegree = 4294967296.0 / 360.0;

// Signed difference a - b in degrees, wrapped into [-180, 180).
double angle_error_deg(angle_t got, double want_deg) {
    double d = std::fmod(got / kUnitsPerDegree - want_deg, 360.0);
    if (d < -180.0) d += 360.0;
    if (d >= 180.0) d -= 360.0;
    return d;
}

double max_atan2_error(int32_t y, int32_t x, double worst) {
    const double want = std::atan2(static_cast<double>(y), static_cast<double>(x)) * 180.0 / kPi;
    return std::fmax(worst, std::fabs(angle_error_deg(atan2_angle(y, x), want)));
}
}  // namespace

TEST_CASE("atan2_angle over every 9-bit (gx, gy) pair", "[angle]") {
    double worst = 0;
    for (int32_t y = -255; y <= 255; ++y)
        for (int32_t x = -255; x <= 255; ++x)
            if (x != 0 || y != 0) worst = max_atan2_error(y, x, worst);
    INFO("worst error " << worst << " deg");
    REQUIRE(worst < 2e-6);
    REQUIRE(atan2_angle(0, 0) == 0);
    REQUIRE(atan2_angle(0, 5) == 0);
    REQUIRE(atan2_angle(5, 0) == kAngleQuarterTurn);
    REQUIRE(atan2_angle(0, -5) == kAngleHalfTurn);
    REQUIRE(atan2_angle(-5, 0) == 3u * kAngleQuarterTurn);
}

TEST_CASE("atan2_angle at random magnitudes up to the int32 extremes", "[angle]") {
    Pcg32 rng(5);
    double worst = 0;
    for (int i = 0; i < 300000; ++i) {
        const int shift = static_cast<int>(rng.next() % 31);
        const int32_t x = static_cast<int32_t>(rng.next()) >> shift;
        const int32_t y = static_cast<int32_t>(rng.next()) >> shift;
        if (x != 0 || y != 0) worst = max_atan2_error(y, x, worst);
    }
    worst = max_atan2_error(INT32_MIN, INT32_MIN, worst);
    worst = max_atan2_error(INT32_MAX, INT32_MIN, worst);
    worst = max_atan2_error(-1, INT32_MIN, worst);
    INFO("worst error " << worst << " deg");
    REQUIRE(worst < 2e-6);
}

TEST_CASE("sin_cos against std::sin and std::cos", "[angle]") {
    Pcg32 rng(6);
    double worst = 0;
    for (int i = 0; i < 400000; ++i) {
        const angle_t a = i < 65536 ? static_cast<angle_t>(i) << 16 : rng.next();
        const double rad = a / 4294967296.0 * 2 * kPi;
        const SinCos sc = sin_cos(a);
        worst = std::fmax(worst, std::fabs(sc.sin.raw / 1073741824.0 - std::sin(rad)));
        worst = std::fmax(worst, std::fabs(sc.cos.raw / 1073741824.0 - std::cos(rad)));
    }
    INFO("worst error " << worst);
    REQUIRE(worst < std::ldexp(1.0, -25));
}

TEST_CASE("degree conversions", "[angle]") {
    REQUIRE(angle_from_deg(90) == kAngleQuarterTurn);
    REQUIRE(angle_from_deg(-90) == 3u * kAngleQuarterTurn);
    REQUIRE(angle_from_deg(360) == 0u);
    REQUIRE(angle_from_deg(540) == kAngleHalfTurn);
    Pcg32 rng(7);
    for (int i = 0; i < 100000; ++i) {
        const q16_16 deg = q16_16::from_raw(static_cast<int32_t>(rng.next()));
        const double want = deg.raw / 65536.0;
        REQUIRE(std::fabs(angle_error_deg(angle_from_deg(deg), want)) <=
                0.5 / kUnitsPerDegree + 1e-12);
        const angle_t a = rng.next();
        const double a_deg = a / kUnitsPerDegree;
        const double signed_deg = a_deg >= 180.0 ? a_deg - 360.0 : a_deg;
        REQUIRE(std::fabs(angle_to_deg(a).raw / 65536.0 - signed_deg) <= 0.5 / 65536.0 + 1e-12);
    }
}

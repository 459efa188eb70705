// Fixed-point numbers whose format lives in the type, plus the rounding and saturating
// integer helpers everything else in core/ builds on. No floating point anywhere.
//
// Rounding: every narrowing step says how it rounds. Two rules are used:
//   half_up    — round to nearest, ties towards +inf: (v + 2^(n-1)) >> n. Cheapest; use on
//                values that are not symmetric around zero (magnitudes, positions >= 0).
//   half_away  — round to nearest, ties away from zero. Symmetric: f(-v) = -f(v).
// Saturation: results that do not fit the destination are clamped to its range; nothing here
// can overflow a signed type (all intermediate products are 64-bit, operand ranges are bounded
// by static_assert on the representation widths).
#pragma once
#include <stdint.h>

#include "base/precondition.h"

namespace qt {

// core/ relies on arithmetic right shift of negative values (implementation-defined before
// C++20, arithmetic on every compiler this project supports). Left shifts of negative values
// are undefined, so they never appear: scaling up is done by multiplication.
static_assert((-3 >> 1) == -2, "arithmetic right shift required");

template <typename T>
struct int_limits;
template <>
struct int_limits<int8_t> {
    static constexpr int64_t lo = -128, hi = 127;
};
template <>
struct int_limits<int16_t> {
    static constexpr int64_t lo = -32768, hi = 32767;
};
template <>
struct int_limits<int32_t> {
    static constexpr int64_t lo = -2147483647LL - 1, hi = 2147483647LL;
};
template <>
struct int_limits<uint8_t> {
    static constexpr int64_t lo = 0, hi = 255;
};
template <>
struct int_limits<uint16_t> {
    static constexpr int64_t lo = 0, hi = 65535;
};

// Clamp a 64-bit value into the range of T.
template <typename T>
constexpr T saturate(int64_t v) {
    return v < int_limits<T>::lo   ? static_cast<T>(int_limits<T>::lo)
           : v > int_limits<T>::hi ? static_cast<T>(int_limits<T>::hi)
                                   : static_cast<T>(v);
}

// |v| for v > INT64_MIN.
constexpr int64_t abs64(int64_t v) {
    QT_PRECONDITION(v != -9223372036854775807LL - 1);
    return v < 0 ? -v : v;
}

// v clamped into [lo, hi], lo <= hi.
constexpr int64_t clamp64(int64_t v, int64_t lo, int64_t hi) {
    QT_PRECONDITION(lo <= hi);
    return v < lo ? lo : v > hi ? hi : v;
}

// 2^n as a 64-bit integer, 0 <= n <= 62.
constexpr int64_t pow2(int n) {
    QT_PRECONDITION(n >= 0 && n <= 62);
    return static_cast<int64_t>(1) << n;
}

// v / 2^n rounded to nearest, ties towards +inf. 0 <= n <= 62, |v| <= 2^62.
constexpr int64_t shr_round_half_up(int64_t v, int n) {
    QT_PRECONDITION(n >= 0 && n <= 62 && v >= -pow2(62) && v <= pow2(62));
    return n == 0 ? v : (v + pow2(n - 1)) >> n;
}

// v / 2^n rounded to nearest, ties away from zero. 0 <= n <= 62, |v| <= 2^62.
constexpr int64_t shr_round_half_away(int64_t v, int n) {
    QT_PRECONDITION(n >= 0 && n <= 62 && v >= -pow2(62) && v <= pow2(62));
    return n == 0 ? v : v >= 0 ? (v + pow2(n - 1)) >> n : -((-v + pow2(n - 1)) >> n);
}

// v / 2^n truncated towards zero (as n halvings by C++'s / would give). 0 <= n <= 63,
// v > INT64_MIN.
constexpr int64_t shr_toward_zero(int64_t v, int n) { return v < 0 ? -((-v) >> n) : v >> n; }

// num / den truncated towards zero (C++'s /) for 0 < den < 2^16: four 32-by-32-bit divisions of
// 16-bit digits (one UDIV each on a Cortex-M3/M4, where a 64-bit division is a library call
// several times longer). Other den: the plain division. |num| <= 2^63 - 1.
constexpr int64_t div_by_small(int64_t num, int64_t den) {
    if (den <= 0 || den >= 65536) return num / den;
    const bool neg = num < 0;
    const uint64_t u = neg ? 0u - static_cast<uint64_t>(num) : static_cast<uint64_t>(num);
    const uint32_t d = static_cast<uint32_t>(den);
    uint32_t r = 0;
    uint64_t q = 0;
    for (int k = 3; k >= 0; --k) {  // r < d < 2^16: each partial dividend fits 32 bits
        const uint32_t part = (r << 16) | static_cast<uint32_t>((u >> (16 * k)) & 0xFFFFu);
        const uint32_t digit = part / d;
        r = part - digit * d;
        q = (q << 16) | digit;
    }
    return neg ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
}

// num / den rounded to nearest, ties away from zero. den != 0, |num|, |den| <= 2^62.
constexpr int64_t div_round_half_away(int64_t num, int64_t den) {
    QT_PRECONDITION(den != 0 && num >= -pow2(62) && num <= pow2(62) && den >= -pow2(62) &&
                    den <= pow2(62));
    const bool neg = (num < 0) != (den < 0);
    const int64_t n = num < 0 ? -num : num;
    const int64_t d = den < 0 ? -den : den;
    const int64_t q = div_by_small(n + d / 2, d);
    return neg ? -q : q;
}

// A signed fixed-point number: real value = raw / 2^Frac. Rep is int16_t or int32_t.
template <int Frac, typename Rep = int32_t>
struct Fixed {
    static_assert(Frac >= 0 && Frac < static_cast<int>(8 * sizeof(Rep)), "fraction bits");
    static_assert(sizeof(Rep) <= 4 && static_cast<Rep>(-1) < 0, "signed 8/16/32-bit rep");
    using rep = Rep;
    static constexpr int frac_bits = Frac;
    static constexpr int64_t one_raw = pow2(Frac);  // raw value of 1.0

    Rep raw;

    static constexpr Fixed from_raw(int64_t r) { return Fixed{saturate<Rep>(r)}; }
    // Integer i, saturated to the representable range.
    static constexpr Fixed from_int(int64_t i) { return from_raw(i * one_raw); }
    // The real number num/den, rounded half away from zero: constants are written as
    // from_ratio(1, 2) for 0.5, so the real formula stands beside the value.
    // |num| * 2^Frac must stay below 2^62.
    static constexpr Fixed from_ratio(int64_t num, int64_t den) {
        return from_raw(div_round_half_away(num * one_raw, den));
    }

    // Largest integer <= value.
    constexpr int32_t floor_int() const { return static_cast<int32_t>(raw >> Frac); }
    // Nearest integer, ties away from zero.
    constexpr int32_t round_int() const {
        return static_cast<int32_t>(shr_round_half_away(raw, Frac));
    }

    friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw == b.raw; }
    friend constexpr bool operator!=(Fixed a, Fixed b) { return a.raw != b.raw; }
    friend constexpr bool operator<(Fixed a, Fixed b) { return a.raw < b.raw; }
    friend constexpr bool operator<=(Fixed a, Fixed b) { return a.raw <= b.raw; }
    friend constexpr bool operator>(Fixed a, Fixed b) { return a.raw > b.raw; }
    friend constexpr bool operator>=(Fixed a, Fixed b) { return a.raw >= b.raw; }
};

using q16_16 = Fixed<16, int32_t>;  // range ±32768, step 1/65536: positions, lengths (px)
using q2_30 = Fixed<30, int32_t>;   // range ±2, step 2^-30: sines, cosines, unit vectors

template <int F, typename R>
constexpr Fixed<F, R> add_sat(Fixed<F, R> a, Fixed<F, R> b) {
    return Fixed<F, R>::from_raw(static_cast<int64_t>(a.raw) + b.raw);
}

template <int F, typename R>
constexpr Fixed<F, R> neg_sat(Fixed<F, R> a) {
    return Fixed<F, R>::from_raw(-static_cast<int64_t>(a.raw));
}

}  // namespace qt

// Fixed-point helpers against double-precision references.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "base/fixed.h"
#include "base/prng.h"
#include "base/wide_mul.h"

using namespace qt;

namespace {
// Round half away from zero, then clamp to [lo, hi]: the reference of every narrowing here.
int64_t ref_round_clamp(double v, int64_t lo, int64_t hi) {
    const double r = std::round(v);  // std::round rounds halves away from zero
    return r < static_cast<double>(lo)   ? lo
           : r > static_cast<double>(hi) ? hi
                                         : static_cast<int64_t>(r);
}
}  // namespace

TEST_CASE("shift-right rounding helpers match their stated rules", "[fixed]") {
    for (int64_t v = -5000; v <= 5000; ++v)
        for (int n = 0; n <= 6; ++n) {
            const double exact = static_cast<double>(v) / std::ldexp(1.0, n);
            REQUIRE(shr_round_half_up(v, n) == static_cast<int64_t>(std::floor(exact + 0.5)));
            REQUIRE(shr_round_half_away(v, n) == static_cast<int64_t>(std::round(exact)));
        }
    // Symmetry of half-away, the reason to use it on signed values.
    REQUIRE(shr_round_half_away(-3, 1) == -2);
    REQUIRE(shr_round_half_away(3, 1) == 2);
    REQUIRE(shr_round_half_up(-3, 1) == -1);
}

TEST_CASE("div_round_half_away for every sign combination", "[fixed]") {
    for (int64_t n = -300; n <= 300; ++n)
        for (int64_t d = -17; d <= 17; ++d) {
            if (d == 0) continue;
            REQUIRE(
                div_round_half_away(n, d) ==
                static_cast<int64_t>(std::round(static_cast<double>(n) / static_cast<double>(d))));
        }
}

TEST_CASE("shr_toward_zero equals C++'s division by 2^n", "[fixed]") {
    for (int64_t v = -1000; v <= 1000; ++v)
        for (int n = 0; n <= 12; ++n) REQUIRE(shr_toward_zero(v, n) == v / pow2(n));
    REQUIRE(shr_toward_zero(-INT64_MAX, 62) == -INT64_MAX / pow2(62));
}

TEST_CASE("div_by_small equals C++'s division", "[fixed]") {
    Pcg32 rng(11);
    for (int i = 0; i < 200000; ++i) {
        // Numerators of every magnitude and sign (|num| < 2^63), divisors below 2^16 and a few
        // beyond (the plain division).
        const int64_t num =
            static_cast<int64_t>((static_cast<uint64_t>(rng.next()) << 31 | rng.next() >> 1) >>
                                 (rng.next() % 63)) *
            (rng.next() % 2 ? 1 : -1);
        const int64_t den = i % 10 == 0 ? static_cast<int64_t>(rng.next() % 4000000) + 1
                                        : static_cast<int64_t>(rng.next() % 65535) + 1;
        REQUIRE(div_by_small(num, den) == num / den);
    }
    for (const int64_t den : {1, 2, 3, 255, 65535})
        for (const int64_t num : {INT64_MAX, -INT64_MAX, int64_t{0}, int64_t{-1}, int64_t{65535}})
            REQUIRE(div_by_small(num, den) == num / den);
}

TEST_CASE("saturate clamps to the destination range", "[fixed]") {
    REQUIRE(saturate<int16_t>(40000) == 32767);
    REQUIRE(saturate<int16_t>(-40000) == -32768);
    REQUIRE(saturate<int16_t>(-1234) == -1234);
    REQUIRE(saturate<uint8_t>(-1) == 0);
    REQUIRE(saturate<uint8_t>(256) == 255);
    REQUIRE(saturate<int32_t>(INT64_C(1) << 40) == INT32_MAX);
    REQUIRE(saturate<int32_t>(-(INT64_C(1) << 40)) == INT32_MIN);
}

TEST_CASE("from_ratio is the nearest representable value", "[fixed]") {
    Pcg32 rng(1);
    for (int i = 0; i < 200000; ++i) {
        const int64_t num = static_cast<int64_t>(rng.next() % 200001) - 100000;
        const int64_t den = static_cast<int64_t>(rng.next() % 1000) + 1;
        const double exact = static_cast<double>(num) / static_cast<double>(den) * 65536.0;
        REQUIRE(q16_16::from_ratio(num, den).raw == ref_round_clamp(exact, INT32_MIN, INT32_MAX));
    }
    REQUIRE(q16_16::from_ratio(1, 2).raw == 32768);
    using q1_15 = Fixed<15, int16_t>;               // a 16-bit format: range [-1, 1)
    REQUIRE(q1_15::from_ratio(1, 1).raw == 32767);  // 1.0 saturates in q1_15
    REQUIRE(q1_15::from_ratio(-1, 1).raw == -32768);
    REQUIRE(q16_16::from_int(40000).raw == INT32_MAX);
}

TEST_CASE("add_sat and neg_sat saturate instead of overflowing", "[fixed]") {
    const q16_16 big = q16_16::from_raw(INT32_MAX - 5);
    REQUIRE(add_sat(big, q16_16::from_int(1)).raw == INT32_MAX);
    REQUIRE(neg_sat(q16_16::from_raw(INT32_MIN)).raw == INT32_MAX);
    REQUIRE(add_sat(q16_16::from_ratio(3, 2), q16_16::from_ratio(1, 4)) ==
            q16_16::from_ratio(7, 4));
    REQUIRE(q16_16::from_ratio(-5, 2).round_int() == -3);
    REQUIRE(q16_16::from_ratio(-5, 2).floor_int() == -3);
    REQUIRE(q16_16::from_ratio(-9, 4).round_int() == -2);
}

TEST_CASE("reciprocal is 2^(len+61)/s rounded half up, against __int128", "[fixed]") {
    Pcg32 rng(11);
    auto check = [](int64_t s) {
        const int len = 64 - __builtin_clzll(static_cast<uint64_t>(s));
        const unsigned __int128 n = static_cast<unsigned __int128>(1) << (len + 61);
        const unsigned __int128 q = n / static_cast<unsigned __int128>(s),
                                rem = n % static_cast<unsigned __int128>(s);
        const int64_t want = static_cast<int64_t>(q + (2 * rem >= static_cast<uint64_t>(s)));
        INFO("s = " << s);
        const Reciprocal got = reciprocal(s);
        REQUIRE(got.len == len);
        REQUIRE(got.m == want);
    };
    for (int bits = 1; bits <= 63; ++bits) {  // powers of two and their neighbours
        const int64_t p = static_cast<int64_t>((static_cast<uint64_t>(1) << bits) - 1u);
        check(p);
        if (p > 1) check(p - 1);
        if (bits < 63) check(p + 1), check(p + 2);
    }
    for (int i = 0; i < 300000; ++i) {
        const int bits = 1 + static_cast<int>(rng.below(63));
        const uint64_t v = (static_cast<uint64_t>(rng.next()) << 32 | rng.next()) >> (64 - bits);
        check(v == 0 ? 1 : static_cast<int64_t>(v));
    }
}

TEST_CASE("wide 64x64 products round half away and saturate, against __int128", "[fixed]") {
    Pcg32 rng(7);
    for (int i = 0; i < 200000; ++i) {
        const int bits_a = static_cast<int>(rng.below(64)),
                  bits_b = static_cast<int>(rng.below(64));
        const int64_t a =
            static_cast<int64_t>((static_cast<uint64_t>(rng.next()) << 32 | rng.next()) >>
                                 (63 - bits_a)) *
            (rng.below(2) ? 1 : -1);
        const int64_t b =
            static_cast<int64_t>((static_cast<uint64_t>(rng.next()) << 32 | rng.next()) >>
                                 (63 - bits_b)) *
            (rng.below(2) ? 1 : -1);
        const int n = static_cast<int>(rng.below(127));
        const __int128 p = static_cast<__int128>(a) * b;
        const __int128 mag = p < 0 ? -p : p;
        __int128 q = n == 0 ? mag : (mag + (static_cast<__int128>(1) << (n - 1))) >> n;
        if (q > INT64_MAX) q = INT64_MAX;
        const int64_t want = static_cast<int64_t>(p < 0 ? -q : q);
        INFO(a << " * " << b << " >> " << n);
        REQUIRE(mul_shr_round(a, b, n) == want);
    }
    REQUIRE(mul_shr_round(INT64_MIN, INT64_MIN, 0) == INT64_MAX);
    REQUIRE(mul_shr_round(INT64_MIN, INT64_MAX, 0) == -INT64_MAX);
    REQUIRE(mul_shr_round(INT64_MIN, INT64_MIN, 126) == 1);  // 2^126 / 2^126
    REQUIRE(mul_shr_round(-3, 1, 1) == -2);                  // -1.5: away from zero
    REQUIRE(mul_shr_round(3, 1, 1) == 2);
}

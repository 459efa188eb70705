// Integer square roots checked by their defining inequality r² <= n < (r+1)².
#include <catch2/catch.hpp>
#include <cstdint>

#include "base/isqrt.h"
#include "base/prng.h"

using namespace qt;

namespace {
bool is_floor_sqrt(unsigned __int128 n, unsigned __int128 r) {
    return r * r <= n && n < (r + 1) * (r + 1);
}
}  // namespace

TEST_CASE("isqrt32 is floor(sqrt) for every n below 2^24 and at random above", "[isqrt]") {
    for (uint32_t n = 0; n < (1u << 24); ++n) {
        if (!is_floor_sqrt(n, isqrt32(n))) FAIL("isqrt32(" << n << ") = " << isqrt32(n));
    }
    Pcg32 rng(3);
    for (int i = 0; i < 1000000; ++i) {
        const uint32_t n = rng.next();
        REQUIRE(is_floor_sqrt(n, isqrt32(n)));
    }
    for (uint32_t r = 65535; r > 60000; --r) {  // around the top squares
        REQUIRE(isqrt32(r * r) == r);
        REQUIRE(isqrt32(r * r - 1) == r - 1);
    }
    REQUIRE(isqrt32(UINT32_MAX) == 65535);
}

TEST_CASE("isqrt64 and isqrt64_round", "[isqrt]") {
    Pcg32 rng(4);
    for (int i = 0; i < 1000000; ++i) {
        const uint64_t n =
            (static_cast<uint64_t>(rng.next()) << 32 | rng.next()) >> (rng.next() % 64);
        const uint32_t r = isqrt64(n);
        REQUIRE(is_floor_sqrt(n, r));
        // Nearest: |rr² - n| is smallest for rr = isqrt64_round(n) among r and r + 1.
        const uint64_t rr = isqrt64_round(n);
        const unsigned __int128 lo = static_cast<unsigned __int128>(r) * r;
        const unsigned __int128 hi = static_cast<unsigned __int128>(r + 1) * (r + 1);
        // n - r² vs (r+1)² - n, both in 4·(...) to compare against (r + 1/2)² exactly.
        const bool nearer_hi = 4 * static_cast<unsigned __int128>(n) > (lo + hi) * 2 - 1;
        REQUIRE(rr == (nearer_hi && r < UINT32_MAX ? r + 1ull : r));
    }
    // Around squares of every size: the root's low bits are found one by one above 2^32.
    for (int bits = 16; bits <= 32; ++bits)
        for (uint64_t d = 0; d < 50; ++d) {
            const uint64_t r = (uint64_t{1} << bits) - 1 - d * 977;
            REQUIRE(isqrt64(r * r) == r);
            REQUIRE(isqrt64(r * r - 1) == r - 1);
            if (r < UINT32_MAX) REQUIRE(isqrt64(r * r + 2 * r) == r);  // (r + 1)² - 1
        }
    REQUIRE(isqrt64(UINT64_MAX) == UINT32_MAX);
    REQUIRE(isqrt64_round(UINT64_MAX) == UINT32_MAX);
    REQUIRE(isqrt64_round(12) == 3);  // sqrt(12) = 3.46
    REQUIRE(isqrt64_round(13) == 4);  // sqrt(13) = 3.61
}

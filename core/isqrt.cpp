#include "isqrt.h"

namespace qt {

namespace {

// Classic digit-by-digit square root in base 4: `bit` walks down the even powers of two.
template <typename U>
U isqrt_bits(U n, U bit) {
    U root = 0;
    while (bit > n) bit >>= 2;
    while (bit != 0) {
        if (n >= root + bit) {
            n -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return root;
}

}  // namespace

uint16_t isqrt32(uint32_t n) {
    return static_cast<uint16_t>(isqrt_bits<uint32_t>(n, uint32_t{1} << 30));
}

uint32_t isqrt64(uint64_t n) {
    return static_cast<uint32_t>(isqrt_bits<uint64_t>(n, uint64_t{1} << 62));
}

uint32_t isqrt64_round(uint64_t n) {
    const uint64_t r = isqrt64(n);
    // r + 1 can reach 2^32 only for n > 2^64 - 2^32; saturate there.
    return static_cast<uint32_t>(n > r * r + r && r < 0xFFFFFFFFu ? r + 1 : r);
}

}  // namespace qt

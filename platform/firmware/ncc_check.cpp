// The NCC dot products (core/target/ncc_match.h) on the Cortex-M target (QEMU), where they take
// the SIMD path (four bytes a step, a row's last step masked when its width is not a multiple
// of four): dot_block and dot_bytes over blocks of every width 1..32 and several heights,
// strides and offsets, each against the plain sum of products computed here. The blocks'
// bytes are a hash of their position, extremes included (0 and 255). Prints one line per width
// and "ncc: all N blocks PASS"; exit status 0 only then.
#include <stdint.h>

#include "semihosting.h"
#include "target/ncc_match.h"

namespace {

constexpr uint32_t kMaxWidth = 32, kStride = 37;  // 37: rows start at every alignment
uint8_t g_a[kMaxWidth * kMaxWidth];
uint8_t g_b[kStride * (kMaxWidth + 1) + 4];

uint8_t byte_at(uint32_t seed, uint32_t i) {
    uint32_t h = (i + 1u) * 2654435761u ^ seed * 40503u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    // One byte in eight is an extreme: the products' largest value and zero are covered.
    return (h & 7u) == 0u ? 255u : (h & 7u) == 1u ? 0u : static_cast<uint8_t>(h >> 24);
}

uint32_t plain_dot(const uint8_t* a, uint32_t w, uint32_t h, const uint8_t* b, uint32_t stride) {
    uint32_t d = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) d += uint32_t{a[y * w + x]} * b[y * stride + x];
    return d;
}

}  // namespace

int main() {
    uint32_t blocks = 0, failed = 0;
    for (uint32_t w = 1; w <= kMaxWidth; ++w) {
        uint32_t width_failed = 0;
        for (uint32_t h = 1; h <= kMaxWidth && w * h <= qt::kNccMaxPixels; h += 7u) {
            for (uint32_t offset = 0; offset < 4u; ++offset) {
                const uint32_t seed = w * 1000u + h * 10u + offset;
                for (uint32_t i = 0; i < w * h; ++i) g_a[i] = byte_at(seed, i);
                for (uint32_t i = 0; i < sizeof g_b; ++i) g_b[i] = byte_at(seed + 7u, i);
                const uint8_t* b = g_b + offset;
                const uint32_t want = plain_dot(g_a, w, h, b, kStride);
                const bool ok = qt::dot_block(g_a, w, h, b, kStride) == want &&
                                (h != 1u || qt::dot_bytes(g_a, b, w) == want);
                ++blocks;
                if (!ok) ++width_failed;
            }
        }
        failed += width_failed;
        sh_write("ncc width ");
        sh_dec(w);
        sh_write(width_failed == 0 ? ": PASS\n" : ": FAIL\n");
    }
    sh_write("ncc: ");
    if (failed == 0) {
        sh_write("all ");
        sh_dec(blocks);
        sh_write(" blocks PASS\n");
    } else {
        sh_dec(failed);
        sh_write(" blocks FAIL\n");
    }
    return failed == 0 ? 0 : 1;
}

// Test-side renditions of docs/gradient.md, written from the document and not from core/:
// the direction rule with plain multiplications, and gradients of a whole frame in memory.
#pragma once
#include <cstdint>
#include <vector>

namespace qt::ref {

// Direction bin per docs/gradient.md, using * where the core and HDL shift and add.
inline uint32_t direction_rule(int gx, int gy) {
    const int ax = gx < 0 ? -gx : gx, ay = gy < 0 ? -gy : gy;
    const int lo = ay <= ax ? ay : ax, hi = ay <= ax ? ax : ay;
    int s = 256 * lo <= 51 * hi ? 0 : 256 * lo <= 171 * hi ? 1 : 2;
    if (ay > ax) s = 4 - s;
    if (gx >= 0 && gy >= 0) return static_cast<uint32_t>(s);
    if (gx < 0 && gy >= 0) return static_cast<uint32_t>(8 - s);
    if (gx < 0) return static_cast<uint32_t>(8 + s);
    return static_cast<uint32_t>((16 - s) % 16);
}

struct RefGradient {
    int gx, gy, mag;
    uint32_t dir;
};

// Central differences with replicated borders over a whole frame held in memory.
inline std::vector<RefGradient> frame_gradients(const std::vector<uint8_t>& px, int w, int h) {
    auto p = [&](int x, int y) {
        x = x < 0 ? 0 : x >= w ? w - 1 : x;
        y = y < 0 ? 0 : y >= h ? h - 1 : y;
        return static_cast<int>(px[static_cast<size_t>(y) * w + x]);
    };
    std::vector<RefGradient> g;
    g.reserve(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int gx = p(x + 1, y) - p(x - 1, y), gy = p(x, y + 1) - p(x, y - 1);
            g.push_back(
                {gx, gy, (gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy), direction_rule(gx, gy)});
        }
    return g;
}

}  // namespace qt::ref

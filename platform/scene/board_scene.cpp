#include "scene/board_scene.h"

#include "base/prng.h"

namespace qt::scene {

namespace {

// Twice the signed area of (a, b, p), in (1/256 px)^2 units; 64-bit because coordinates reach
// 2^18 and products 2^36.
int64_t cross(SubPixel a, SubPixel b, SubPixel p) {
    return static_cast<int64_t>(b.x - a.x) * (p.y - a.y) -
           static_cast<int64_t>(b.y - a.y) * (p.x - a.x);
}

bool inside_convex(const SubPixel (&c)[4], SubPixel p) {
    bool has_neg = false, has_pos = false;
    for (int i = 0; i < 4; ++i) {
        const int64_t s = cross(c[i], c[(i + 1) % 4], p);
        has_neg = has_neg || s < 0;
        has_pos = has_pos || s > 0;
    }
    return !(has_neg && has_pos);
}

int clamp255(int v) { return v < 0 ? 0 : v > 255 ? 255 : v; }

}  // namespace

BoardScene default_board_scene() {
    BoardScene s;
    // Corners in pixels ×256: a board turned by about 12° with perspective foreshortening.
    s.corners[0] = {188 * 256, 112 * 256};
    s.corners[1] = {452 * 256, 150 * 256};
    s.corners[2] = {430 * 256, 352 * 256};
    s.corners[3] = {160 * 256, 318 * 256};
    s.seed = 2026;
    return s;
}

io::GreyImage render_board(const BoardScene& scene) {
    io::GreyImage img(scene.width, scene.height);
    Pcg32 rng(scene.seed);
    // Low-contrast blobs: centre (px), radius (px), level offset (grey levels).
    struct Blob {
        int x, y, r, level;
    } blobs[12];
    for (Blob& b : blobs) {
        b.x = static_cast<int>(rng.below(static_cast<uint32_t>(scene.width)));
        b.y = static_cast<int>(rng.below(static_cast<uint32_t>(scene.height)));
        b.r = 8 + static_cast<int>(rng.below(40));
        b.level = static_cast<int>(rng.below(31)) - 15;
    }
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            // Shading 40..100 across the frame plus stripes of period 32 px, amplitude 6.
            int v = 40 + 40 * x / scene.width + 20 * y / scene.height;
            v += ((x + 2 * y) & 31) < 16 ? 6 : 0;
            for (const Blob& b : blobs) {
                const int dx = x - b.x, dy = y - b.y;
                if (dx * dx + dy * dy <= b.r * b.r) v += b.level;
            }
            int covered = 0;  // of 16 sub-samples at offsets (i + 0.5)/4 - 0.5 px
            for (int sy = 0; sy < 4; ++sy)
                for (int sx = 0; sx < 4; ++sx) {
                    const SubPixel p{x * 256 - 96 + sx * 64, y * 256 - 96 + sy * 64};
                    covered += inside_convex(scene.corners, p) ? 1 : 0;
                }
            v += (scene.board_level - v) * covered / 16;
            const int a = scene.noise_amplitude;
            v += static_cast<int>(rng.below(static_cast<uint32_t>(2 * a + 1))) - a;
            img.at(x, y) = static_cast<uint8_t>(clamp255(v));
        }
    }
    return img;
}

}  // namespace qt::scene

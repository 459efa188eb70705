#include "target/float/template_pose.h"

#include "target/float/target_kalman.h"  // homography_jacobian

namespace qt {

bool TemplatePose::jacobian(float j[4]) const { return homography_jacobian(h, cx, cy, j); }

bool warp_negligible(const float j[4], uint8_t w, uint8_t h) {
    // The largest move is at a corner: |(J − I)·(±hw, ±hh)| per axis <= |row|·(hw, hh).
    const float hw = 0.5f * static_cast<float>(w - 1), hh = 0.5f * static_cast<float>(h - 1);
    auto mag = [](float v) { return v < 0 ? -v : v; };
    const float mx = mag(j[0] - 1.0f) * hw + mag(j[1]) * hh;
    const float my = mag(j[2]) * hw + mag(j[3] - 1.0f) * hh;
    constexpr float kNegligiblePx = 1.0f / 16.0f;
    return mx < kNegligiblePx && my < kNegligiblePx;
}

bool warp_template(const uint8_t* in, uint8_t w, uint8_t h, const float j[4], uint8_t* out) {
    const float det = j[0] * j[3] - j[1] * j[2];
    // NaN fails both comparisons; an infinite entry makes det infinite or NaN.
    if (!(det >= kWarpMinDet && det <= kWarpMaxDet) || w == 0 || h == 0) return false;
    // j⁻¹ = [j3, −j1; −j2, j0] / det.
    const float a = j[3] / det, b = -j[1] / det, c = -j[2] / det, d = j[0] / det;
    // A motion this far from a rotation-and-scale is not one a target's look survives (and NaN
    // or an infinity fails the test).
    auto bounded = [](float v) { return v >= -kWarpMaxEntry && v <= kWarpMaxEntry; };
    if (!bounded(a) || !bounded(b) || !bounded(c) || !bounded(d)) return false;
    const float cx = 0.5f * static_cast<float>(w - 1), cy = 0.5f * static_cast<float>(h - 1);
    const float last_x = static_cast<float>(w - 1), last_y = static_cast<float>(h - 1);
    for (int y = 0; y < h; ++y) {
        const float dy = static_cast<float>(y) - cy;
        for (int x = 0; x < w; ++x) {
            const float dx = static_cast<float>(x) - cx;
            float sx = cx + a * dx + b * dy, sy = cy + c * dx + d * dy;
            // Clamped to the template (a finite j⁻¹ keeps sx, sy finite): its edges extend out.
            sx = sx < 0.0f ? 0.0f : sx > last_x ? last_x : sx;
            sy = sy < 0.0f ? 0.0f : sy > last_y ? last_y : sy;
            const int x0 = static_cast<int>(sx), y0 = static_cast<int>(sy);
            const int x1 = x0 + 1 < w ? x0 + 1 : x0, y1 = y0 + 1 < h ? y0 + 1 : y0;
            const float fx = sx - static_cast<float>(x0), fy = sy - static_cast<float>(y0);
            auto px = [&](int u, int v) { return static_cast<float>(in[v * w + u]); };
            const float top = px(x0, y0) + fx * (px(x1, y0) - px(x0, y0));
            const float bottom = px(x0, y1) + fx * (px(x1, y1) - px(x0, y1));
            const float v = top + fy * (bottom - top) + 0.5f;  // within [0.5, 255.5]
            out[y * w + x] = static_cast<uint8_t>(v >= 255.0f ? 255.0f : v);
        }
    }
    return true;
}

}  // namespace qt

#include "scene/board_sequence.h"

#include <cmath>

namespace qt::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBarLevel = 24;  // grey level of a bar (plus the rendered noise's low bits)

}  // namespace

BoardScene turned_board(const BoardScene& base, double angle_deg, double dx, double dy) {
    BoardScene s = base;
    double cx = 0, cy = 0;
    for (const auto& c : s.corners) {
        cx += c.x / 256.0 / 4;
        cy += c.y / 256.0 / 4;
    }
    const double a = angle_deg * kPi / 180, ca = std::cos(a), sa = std::sin(a);
    for (auto& c : s.corners) {
        const double x = c.x / 256.0 - cx, y = c.y / 256.0 - cy;
        c.x = static_cast<int32_t>(std::lround((cx + x * ca - y * sa + dx) * 256));
        c.y = static_cast<int32_t>(std::lround((cy + x * sa + y * ca + dy) * 256));
    }
    return s;
}

void draw_bar(io::GreyImage& img, SubPixel a, SubPixel b, double half_width) {
    const double ax = a.x / 256.0, ay = a.y / 256.0, dx = b.x / 256.0 - ax, dy = b.y / 256.0 - ay;
    const double len = std::hypot(dx, dy);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (std::fabs((x - ax) * dy - (y - ay) * dx) / len <= half_width)
                img.at(x, y) = static_cast<uint8_t>(kBarLevel + (img.at(x, y) & 7));
}

BoardSequenceFrame board_sequence_frame(int f, int shrink) {
    BoardScene base = default_board_scene();
    base.width /= shrink;
    base.height /= shrink;
    for (auto& c : base.corners) c = {c.x / shrink, c.y / shrink};
    BoardSequenceFrame d;
    d.scene = turned_board(base, (f - 6) * 2.5, (6.0 * f - 33) / shrink, (2.0 * f - 11) / shrink);
    d.scene.seed = 100 + static_cast<uint64_t>(f);
    d.image = render_board(d.scene);
    d.hidden = f >= kFirstHiddenFrame && f <= kLastHiddenFrame;
    if (d.hidden) {
        draw_bar(d.image, d.scene.corners[0], d.scene.corners[1]);  // top
        draw_bar(d.image, d.scene.corners[2], d.scene.corners[3]);  // bottom
    }
    return d;
}

BoardSequenceFrame sized_sequence_frame(const BoardMotionSpec& spec, int f, int width, int height) {
    const double s = std::fmin(width / 640.0, height / 480.0);
    const double ox = (width - 640 * s) / 2, oy = (height - 480 * s) / 2;
    BoardScene base = default_board_scene();
    base.width = width;
    base.height = height;
    for (auto& c : base.corners)
        c = {static_cast<int32_t>(std::lround((c.x / 256.0 * s + ox) * 256)),
             static_cast<int32_t>(std::lround((c.y / 256.0 * s + oy) * 256))};
    const int t = f - spec.turn_zero;
    BoardSequenceFrame d;
    // At s = 1 the same doubles as board_sequence_frame's 6f − 33 and 2f − 11.
    d.scene =
        turned_board(base, t * spec.turn_deg, spec.dx * (f - 5.5) * s, spec.dy * (f - 5.5) * s);
    d.scene.seed = 100 + static_cast<uint64_t>(f);
    d.image = render_board(d.scene);
    d.hidden = f >= spec.first_hidden && f <= spec.last_hidden;
    // Bars as wide as the scale makes them, but never narrower than at 640 × 480: their edges
    // stay beyond the tracker's gate (kBarHalfWidth).
    const double half_width = kBarHalfWidth * std::fmax(s, 1.0);
    if (d.hidden) {
        if (spec.hide_top) draw_bar(d.image, d.scene.corners[0], d.scene.corners[1], half_width);
        if (spec.hide_bottom) draw_bar(d.image, d.scene.corners[2], d.scene.corners[3], half_width);
    }
    return d;
}

}  // namespace qt::scene

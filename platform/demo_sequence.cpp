#include "demo_sequence.h"

#include <cmath>
#include <cstdio>

#include "board_runner.h"
#include "board_scene.h"
#include "overlay.h"
#include "png_writer.h"

namespace qt::cli {

namespace {

constexpr int kFrames = 12;
constexpr double kPi = 3.14159265358979323846;

// Frame f: the default board turned by (f − 6)·2.5° about its centre and moved by
// (6f − 33, 2f − 11) px, corners in 1/256 px.
scene::BoardScene frame_scene(int f) {
    scene::BoardScene s = scene::default_board_scene();
    double cx = 0, cy = 0;
    for (const auto& c : s.corners) {
        cx += c.x / 256.0 / 4;
        cy += c.y / 256.0 / 4;
    }
    const double a = (f - 6) * 2.5 * kPi / 180, ca = std::cos(a), sa = std::sin(a);
    for (auto& c : s.corners) {
        const double x = c.x / 256.0 - cx, y = c.y / 256.0 - cy;
        c.x = static_cast<int32_t>(std::lround((cx + x * ca - y * sa + 6.0 * f - 33) * 256));
        c.y = static_cast<int32_t>(std::lround((cy + x * sa + y * ca + 2.0 * f - 11) * 256));
    }
    s.seed = 100 + static_cast<uint64_t>(f);
    return s;
}

double px(q16_16 v) { return v.raw / 65536.0; }

}  // namespace

bool run_demo_sequence(const std::string& out_dir) {
    std::printf("board sequence: %d frames 640x480, lines (red), quadrangle (green), corners (yellow, "
                "the first cyan), the truth's corners (magenta dots)\n", kFrames);
    for (int f = 0; f < kFrames; ++f) {
        const scene::BoardScene sc = frame_scene(f);
        const scene::GreyImage frame = scene::render_board(sc);
        DetectResult r;
        if (!detect_board(frame, BoardParams{}, r)) {
            std::fprintf(stderr, "quadtrack demo: frame %d: %s\n", f, status_name(r.status));
            return false;
        }
        io::RgbImage pic = io::RgbImage::from_grey(frame, 60);
        for (const Segment& l : r.lines) pic.line(px(l.x1), px(l.y1), px(l.x2), px(l.y2), {255, 50, 50});
        // The truth, as the scene generator placed it: in its order TL, TR, BR, BL.
        for (const auto& c : sc.corners) pic.ring(c.x / 256.0, c.y / 256.0, 1, {255, 0, 255});
        char name[32];
        std::snprintf(name, sizeof name, "board_%02d.png", f);
        if (r.quads.empty()) {
            std::printf("frame %2d: %2zu lines, no quadrangle", f, r.lines.size());
        } else {
            const Quad& q = r.quads[0];
            for (int i = 0; i < 4; ++i) {
                const Point16 a = q.corners[i], b = q.corners[(i + 1) & 3];
                pic.line(px(a.x), px(a.y), px(b.x), px(b.y), {60, 255, 60});
            }
            for (int i = 0; i < 4; ++i) {
                const io::Rgb colour = i == 0 ? io::Rgb{0, 230, 255} : io::Rgb{255, 230, 0};
                pic.ring(px(q.corners[i].x), px(q.corners[i].y), 4, colour);
                pic.ring(px(q.corners[i].x), px(q.corners[i].y), 5, colour);
            }
            // Truth TL, TR, BR, BL against detected corners 0, 3, 2, 1 (anti-clockwise as seen).
            double worst = 0;
            const int truth_of[4] = {0, 3, 2, 1};
            for (int i = 0; i < 4; ++i) {
                const auto& t = sc.corners[truth_of[i]];
                worst = std::fmax(worst, std::hypot(px(q.corners[i].x) - t.x / 256.0, px(q.corners[i].y) - t.y / 256.0));
            }
            std::printf("frame %2d: %2zu lines, quad (%.1f,%.1f) (%.1f,%.1f) (%.1f,%.1f) (%.1f,%.1f) score %.2f, "
                        "worst corner error %.2f px",
                        f, r.lines.size(), px(q.corners[0].x), px(q.corners[0].y), px(q.corners[1].x),
                        px(q.corners[1].y), px(q.corners[2].x), px(q.corners[2].y), px(q.corners[3].x),
                        px(q.corners[3].y), q.score.raw / 65536.0, worst);
        }
        std::printf(" -> %s\n", name);
        std::string error;
        if (!io::write_png(out_dir + "/" + name, pic.width, pic.height, 3, pic.pixels, error)) {
            std::fprintf(stderr, "quadtrack demo: %s\n", error.c_str());
            return false;
        }
    }
    return true;
}

}  // namespace qt::cli

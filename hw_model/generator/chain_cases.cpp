#include "chain_cases.h"

#include <cstdio>

#include "api/result_text.h"
#include "base/prng.h"
#include "quads/board_detector.h"
#include "scene/board_sequence.h"
#include "scene/line_scene.h"
#include "tracking/quad_tracker.h"
#include "tracking/tracking_mode.h"

namespace qt::vec {

std::vector<ChainCase> chain_cases() {
    std::vector<ChainCase> cases;
    {  // The demo's moving board at half size, frames 2..9: bars hide the top and bottom sides
        // in the fourth to sixth.
        ChainCase c{"board_motion_qvga", {}};
        for (int f = 2; f <= 9; ++f) c.frames.push_back(scene::board_sequence_frame(f, 2).image);
        cases.push_back(c);
    }
    {  // Three shapes over blobs and texture, blurred and noisy: a cluttered frame.
        scene::SceneOptions o;
        o.noise_sigma = 5;
        o.blur_sigma = 0.8;
        o.clutter_blobs = 25;
        o.clutter_texture = 20;
        o.seed = 31;
        cases.push_back({"clutter_qvga", {scene::random_polygon_scene(o, 3, 30, 60).render()}});
    }
    {  // The worst frames known for the chain's budget: every pixel an independent grey level
        // (a camera at high gain in the dark, gravel, foliage), then 150 straight strokes of
        // random grey crossing the frame (edges and lines everywhere).
        ChainCase c{"stress_qvga", {}};
        Pcg32 rng(2026);
        io::GreyImage noise(320, 240);
        for (uint8_t& p : noise.pixels) p = static_cast<uint8_t>(rng.below(256));
        c.frames.push_back(noise);
        scene::SceneOptions o;
        o.background = 120;
        scene::LineScene strokes(o);
        for (int k = 0; k < 150; ++k) {
            const scene::Point2 a{static_cast<double>(rng.below(320)),
                                  static_cast<double>(rng.below(240))};
            scene::Point2 b{static_cast<double>(rng.below(320)),
                            static_cast<double>(rng.below(240))};
            if (a.x == b.x && a.y == b.y) b.x = a.x + 1;
            // One draw per statement: the order of a call's arguments is unspecified.
            const double width = 1.0 + rng.below(3);
            const uint8_t level = static_cast<uint8_t>(rng.below(256));
            strokes.add_line(a, b, width, level);
        }
        c.frames.push_back(strokes.render());
        cases.push_back(c);
    }
    return cases;
}

std::string frame_name(const ChainCase& c, size_t k) {
    char suffix[24];
    std::snprintf(suffix, sizeof suffix, "_%02zu", k);
    return c.name + suffix;
}

std::string text_name(const ChainCase& c, bool tracking_mode) {
    return tracking_mode ? c.name + "-bands" : c.name;
}

std::string format_pgm(const io::GreyImage& img) {
    std::string s =
        "P5\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n255\n";
    s.append(img.pixels.begin(), img.pixels.end());
    return s;
}

std::vector<std::string> chain_texts(const std::vector<ChainCase>& cases, bool tracking_mode) {
    static BoardDetectorQvga det;
    const BoardParams params;
    QuadTracker tracker(default_quad_tracker_params(320, 240));
    TrackingModeParams mode_params;
    mode_params.enabled = tracking_mode;
    TrackingMode mode(mode_params);
    std::vector<std::string> texts;
    for (const ChainCase& c : cases) {
        tracker.reset();
        mode.reset();
        BandWindow* window = nullptr;
        std::string text;
        for (size_t k = 0; k < c.frames.size(); ++k) {
            const io::GreyImage& frame = c.frames[k];
            if (det.begin_frame(static_cast<uint16_t>(frame.width),
                                static_cast<uint16_t>(frame.height), params,
                                window) != Status::ok) {
                text += "error: frame does not fit BoardDetectorQvga\n";
                break;
            }
            for (int y = 0; y < frame.height; ++y)
                det.push_row(frame.row(y), static_cast<uint16_t>(frame.width));
            const Status status = det.finish();
            const TrackedQuad track = tracker.step(det.lines().lines(), det.lines().line_count(),
                                                   det.quads(), det.quad_count());
            window = mode.plan(track);
            write_frame_text(frame_name(c, k).c_str(), det, status, track,
                             tracker.stats().lost_reason,
                             [&](const char* line, size_t length) { text.append(line, length); });
        }
        texts.push_back(text);
    }
    return texts;
}

}  // namespace qt::vec

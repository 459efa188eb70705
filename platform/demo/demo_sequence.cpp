#include "demo/demo_sequence.h"

#include <cmath>
#include <cstdio>

#include "host/board_runner.h"
#include "host/draw_results.h"
#include "io/error_line.h"
#include "io/overlay.h"
#include "io/png_writer.h"
#include "scene/board_sequence.h"
#include "tracking/quad_tracker.h"

namespace qt::cli {

namespace {

double px(q16_16 v) { return v.raw / 65536.0; }

// "D P D T": side i detected, predicted or taken back from the detection.
void side_letters(const TrackedQuad& t, uint8_t taken_back, char (&text)[8]) {
    for (int i = 0; i < 4; ++i) {
        text[2 * i] = (taken_back >> i) & 1 ? 'T' : (t.detected >> i) & 1 ? 'D' : 'P';
        text[2 * i + 1] = i < 3 ? ' ' : '\0';
    }
}

}  // namespace

double worst_corner_error(const TrackedQuad& t, const scene::BoardScene& truth) {
    // The truth is TL, TR, BR, BL (clockwise as seen); detect's order runs the other way.
    double best = 1e30;
    for (int r = 0; r < 4; ++r) {
        double worst = 0;
        for (int i = 0; i < 4; ++i) {
            const auto& c = truth.corners[(r + 4 - i) % 4];
            worst = std::fmax(worst, std::hypot(px(t.corners[i].x) - c.x / 256.0,
                                                px(t.corners[i].y) - c.y / 256.0));
        }
        best = std::fmin(best, worst);
    }
    return best;
}

QuadTrackerParams demo_tracker_params(LineModel model, uint16_t width, uint16_t height) {
    QuadTrackerParams p = default_quad_tracker_params(width, height);
    p.shape = sized_quad_params(BoardParams{}.quads, height);
    p.lines.model = model;
    return p;
}

bool track_board_sequence(const scene::BoardMotionSpec& spec, int width, int height,
                          const QuadTrackerParams& params, std::vector<BoardTrackFrame>& out,
                          std::string& error) {
    out.clear();
    const uint8_t bin = host::choose_bin(width, height, 0, error);
    if (bin == 0) return false;
    QuadTracker tracker(params);
    for (int f = 0; f < spec.frames; ++f) {
        const scene::BoardSequenceFrame d = scene::sized_sequence_frame(spec, f, width, height);
        host::DetectResult r;
        if (!host::detect_board(d.image, BoardParams{}, r, bin)) {
            error = "frame " + std::to_string(f) + ": " + status_name(r.status);
            return false;
        }
        BoardTrackFrame k;
        k.quad = tracker.step(r.lines.data(), static_cast<uint16_t>(r.lines.size()), r.quads.data(),
                              static_cast<uint16_t>(r.quads.size()));
        host::to_input_pixels(r, width, height);
        host::to_input_pixels(k.quad, bin);
        k.lost = tracker.stats().lost_reason;
        k.taken_back = tracker.stats().taken_back;
        if (k.quad.state != TrackState::none)
            k.worst_error_px = worst_corner_error(k.quad, d.scene);
        k.hidden = d.hidden;
        k.lines = std::move(r.lines);
        out.push_back(std::move(k));
    }
    return true;
}

bool run_demo_sequence(const std::string& out_dir) {
    std::printf(
        "board sequence: %d frames 640x480, the board turning 2.5 deg and moving 6.3 px a frame; "
        "in frames "
        "%d-%d dark bars hide its top and bottom sides.\n"
        "  tracked with the turn model (quadtrack track --model turn) and, for comparison, the "
        "paper's 3KF "
        "(--model paper); pictures and sides are the turn model's\n"
        "  pictures: lines (red), detected sides (solid green), predicted sides (dashed orange), "
        "corners "
        "(yellow rings, the first cyan), the truth's corners (magenta dots)\n"
        "  sides: D detected, P predicted, T taken back from the detection, in corner order "
        "(left, bottom, right, top)\n",
        scene::kBoardSequenceFrames, scene::kFirstHiddenFrame, scene::kLastHiddenFrame);
    std::vector<BoardTrackFrame> turn, paper;
    std::string error;
    if (!track_board_sequence(scene::kDemoSequence, 640, 480,
                              demo_tracker_params(LineModel::turn, 640, 480), turn, error) ||
        !track_board_sequence(scene::kDemoSequence, 640, 480,
                              demo_tracker_params(LineModel::closest_points, 640, 480), paper,
                              error)) {
        qt::io::print_error_line(stderr, "quadtrack demo: %s", error.c_str());
        return false;
    }
    for (int f = 0; f < scene::kBoardSequenceFrames; ++f) {
        const scene::BoardSequenceFrame d = scene::board_sequence_frame(f);
        const scene::BoardScene& sc = d.scene;
        const BoardTrackFrame& tf = turn[static_cast<size_t>(f)];
        const BoardTrackFrame& pf = paper[static_cast<size_t>(f)];
        const TrackedQuad& t = tf.quad;
        const TrackedQuad& p = pf.quad;
        io::RgbImage pic = io::RgbImage::from_grey(d.image, 60);
        host::draw_lines(pic, tf.lines);
        // The truth, as the scene generator placed it: in its order TL, TR, BR, BL.
        for (const auto& c : sc.corners) pic.ring(c.x / 256.0, c.y / 256.0, 1, {255, 0, 255});
        char name[32];
        std::snprintf(name, sizeof name, "board_%02d.png", f);
        std::printf("frame %2d: %2zu lines%s, ", f, tf.lines.size(),
                    d.hidden ? ", bars over top+bottom" : "");
        if (t.state == TrackState::none) {
            std::printf("no quadrangle");
        } else {
            host::draw_tracked(pic, t);
            char sides[8];
            side_letters(t, tf.taken_back, sides);
            std::printf(
                "quad (%s, sides %s) track %u, corners (%.1f,%.1f) (%.1f,%.1f) (%.1f,%.1f) "
                "(%.1f,%.1f), "
                "worst corner error %.2f px",
                track_state_name(t.state), sides, t.track_id, px(t.corners[0].x),
                px(t.corners[0].y), px(t.corners[1].x), px(t.corners[1].y), px(t.corners[2].x),
                px(t.corners[2].y), px(t.corners[3].x), px(t.corners[3].y), tf.worst_error_px);
        }
        if (tf.lost != QuadTrackLost::none)
            std::printf(", a track was lost: %s", quad_track_lost_name(tf.lost));
        if (p.state == TrackState::none) {
            std::printf("; 3KF: none");
        } else {
            char sides[8];
            side_letters(p, pf.taken_back, sides);
            std::printf("; 3KF: sides %s, %.2f px", sides, pf.worst_error_px);
        }
        if (pf.lost != QuadTrackLost::none)
            std::printf(", lost: %s", quad_track_lost_name(pf.lost));
        std::printf(" -> %s\n", name);
        if (!io::write_png(out_dir + "/" + name, pic.width, pic.height, 3, pic.pixels, error)) {
            qt::io::print_error_line(stderr, "quadtrack demo: %s", error.c_str());
            return false;
        }
    }
    return true;
}

}  // namespace qt::cli

// The demo's board sequence (platform/scene/board_sequence.h) detected and tracked
// (core/tracking/quad_tracker.h) frame by frame, each frame written as an overlay picture with a
// one-line summary on stdout; and the run behind it, shared with the tests and benches: any
// board sequence at any camera size, one tracker, corner errors against the truth.
#pragma once
#include <string>
#include <vector>

#include "quads/board_detector.h"
#include "scene/board_sequence.h"
#include "tracking/quad_tracker.h"

namespace qt::cli {

// Writes board_00.png ... under out_dir (which exists). Returns false after printing an error.
bool run_demo_sequence(const std::string& out_dir);

// One frame of a tracked board sequence.
struct BoardTrackFrame {
    TrackedQuad quad;
    QuadTrackLost lost = QuadTrackLost::none;  // QuadTracker::stats() of the frame
    uint8_t taken_back = 0;
    double worst_error_px = -1;  // worst corner distance from the truth, px; -1 without a quad
    bool hidden = false;         // bars over sides in this frame
    std::vector<Segment> lines;  // the lines stage's lines
};

// The worst distance of t's corners from the truth's (the scene's corners, in any rotation of
// their anti-clockwise order: which corner comes first is detect's business), px.
double worst_corner_error(const TrackedQuad& t, const scene::BoardScene& truth);

// The demo's tracker for a width × height frame: default_quad_tracker_params() with
// BoardParams{}' shape limits, and `model`.
QuadTrackerParams demo_tracker_params(LineModel model, uint16_t width, uint16_t height);

// Frames 0 .. spec.frames − 1 of scene::sized_sequence_frame(spec, f, width, height), binned
// as `quadtrack track` bins them (choose_bin's automatic factor N), detected with BoardParams{}
// and tracked with `params` (sized for the binned frame, ⌊width/N⌋ × ⌊height/N⌋); corners and
// lines in the input's pixels. Returns false with one line in `error` when no factor fits or a
// frame cannot be detected (an error status).
bool track_board_sequence(const scene::BoardMotionSpec& spec, int width, int height,
                          const QuadTrackerParams& params, std::vector<BoardTrackFrame>& out,
                          std::string& error);

}  // namespace qt::cli

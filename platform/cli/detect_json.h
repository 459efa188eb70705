// The one definition of `quadtrack detect`'s JSON (see docs/cli.md), written on
// one line so a sequence of frames is JSON Lines:
//   {"width":W,"height":H,"bin":N,"status":"ok",
//    "lines":[{"x1":..,"y1":..,"x2":..,"y2":..,"rho":..,"theta_deg":..}, ...],
//    "quads":[{"corners":[[x,y],[x,y],[x,y],[x,y]],"score":..,
//              "display_homography":[[a,b,c],[d,e,f],[g,h,1]]}, ...]}
// W × H is the input frame; bin is the factor it was binned by before detection (1: not
// binned; docs/cli.md), and every coordinate is in the input's pixels all the same.
// Pixels with the origin at the centre of pixel (0, 0), x right, y down; rho >= 0 and
// theta_deg in [0, 360) the direction of the line's normal from the origin (y down: clockwise
// on screen); corners anti-clockwise as seen, the first with the smallest x + y (top-left);
// score = share of the perimeter with edge evidence of each side's polarity (quad_refine.h),
// 0..1; display_homography maps display pixels
// (u, v, 1) onto image pixels (x·w, y·w, w), or is null when it cannot be represented.
//
// `quadtrack track` writes one line per frame with the same pieces (docs/cli.md):
//   {"frame":K,"width":W,"height":H,"bin":N,"status":"ok","state":"none"|"started"|"tracking",
//    "track_id":N,
//    "quad":{"corners":[[x,y],[x,y],[x,y],[x,y]],"source":["detected"|"predicted", x4],
//            "display_homography":[[..],[..],[..]]}|null,
//    "lost":null|"side_unseen"|"shape"|"saturated"|"detection_disagrees",
//    "lines":[...as detect...]}
// frame counts from 0 in the sequence's order; track_id is 1, 2, ... (a new one each time a track
// starts), 0 when state is "none" (then quad is null); source[i] tells whether side i (corner i
// -> corner i + 1) was matched to a line detected in this frame or predicted by its tracker;
// lost names why a track ended in this frame (a new one may have started in the same frame).
#pragma once
#include <string>

#include "host/board_runner.h"
#include "tracking/quad_tracker.h"

namespace qt::cli {

std::string detect_json(const host::DetectResult& result, uint16_t display_width,
                        uint16_t display_height);

// score: the tracked board's evidence share this frame (evidence_share); lost_reason:
// QuadTracker::stats().lost_reason; with_lines: false leaves "lines" out.
std::string track_json(int frame, const host::DetectResult& result, const TrackedQuad& quad,
                       q16_16 score, QuadTrackLost lost_reason, uint16_t display_width,
                       uint16_t display_height, bool with_lines = true);

}  // namespace qt::cli

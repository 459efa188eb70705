// The one definition of `quadtrack detect`'s JSON (see README, "quadtrack detect"), written on
// one line so a sequence of frames is JSON Lines:
//   {"width":W,"height":H,"status":"ok",
//    "lines":[{"x1":..,"y1":..,"x2":..,"y2":..,"rho":..,"theta_deg":..}, ...],
//    "quads":[{"corners":[[x,y],[x,y],[x,y],[x,y]],"score":..,
//              "display_homography":[[a,b,c],[d,e,f],[g,h,1]]}, ...]}
// Pixels with the origin at the centre of pixel (0, 0), x right, y down; rho >= 0 and
// theta_deg in [0, 360) the direction of the line's normal from the origin (y down: clockwise
// on screen); corners anti-clockwise as seen, the first with the smallest x + y (top-left);
// score = covered share of the perimeter, 0..1; display_homography maps display pixels
// (u, v, 1) onto image pixels (x·w, y·w, w), or is null when it cannot be represented.
#pragma once
#include <string>

#include "board_runner.h"

namespace qt::cli {

std::string detect_json(const DetectResult& result, uint16_t display_width, uint16_t display_height);

}  // namespace qt::cli

// Baseline for benchmarks: the rectangle finder of OpenCV's samples/cpp/squares.cpp, the recipe
// users copy to find a board-like quadrangle, re-implemented on a single grey channel. Built
// only when OpenCV is installed (target quadtrack_opencv_squares); nothing in core/, the tests
// or the main build depends on it.
//
// Recipe (per frame): pyrDown + pyrUp to suppress noise; then for each of threshold_levels
// levels l: l = 0 → Canny(0, canny_high, aperture 5) dilated by a 3×3 square, l ≥ 1 → the
// binary mask grey ≥ (l + 1)·255 / threshold_levels (integer division); findContours (list,
// simple chains); approxPolyDP with ε = approx_epsilon · closed arc length; keep 4-vertex
// convex polygons with |area| > min_area_px2 whose largest |cos| of the corner angles is below
// max_cosine. All four corners are tested (the sample itself skips the first one).
#pragma once
#include <array>
#include <vector>

#include "io/grey_image.h"
#include "scene/line_scene.h"

namespace qt::bench {

struct SquaresParams {
    int threshold_levels = 11;     // N: level 0 is Canny, levels 1..N-1 are plain thresholds
    double approx_epsilon = 0.02;  // approxPolyDP tolerance as a fraction of the arc length
    double min_area_px2 = 1000;    // minimum |contourArea| of the 4-gon, px²
    double max_cosine = 0.3;       // every corner's |cos| must be below this
    int canny_high = 50;           // Canny upper threshold (lower is 0, aperture 5)
};

// Every quadrangle the squares.cpp recipe accepts, corners as approxPolyDP returns them
// (integer contour pixels, pixel centres at integer coordinates), reordered anti-clockwise as
// seen in the image (y down) starting with the corner of smallest x + y. Like the sample, the
// same board usually appears several times (once per level that finds it), and a threshold
// level below the whole background yields the image frame itself (corners (0, 0) .. (w-1, h-1)).
std::vector<std::array<scene::Point2, 4>> opencv_squares(const io::GreyImage& grey,
                                                         const SquaresParams& p = {});

// The one a user would pick: the largest-area accepted quadrangle, if any. Quadrangles with a
// corner on the image's outermost two pixel rows/columns are skipped: they are the frame of an
// all-bright threshold mask (or a board clipped by the frame), never the board's own corners.
// Returns false (corners untouched) when none is left.
bool opencv_best_square(const io::GreyImage& grey, std::array<scene::Point2, 4>& corners,
                        const SquaresParams& p = {});

}  // namespace qt::bench

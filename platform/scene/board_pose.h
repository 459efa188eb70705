// A rectangular board (a display of a given aspect) seen by a pinhole camera: its pose, its
// projected corners, a random placement that keeps it inside the frame, and an arm-like
// occluder over part of one side. Shared by the generated board benchmark
// (board_bench_scene.h) and the boards composited onto photographs (photo_board_scene.h).
// Host only (heap, double); randomness from qt::Pcg32, arithmetic from det_math.h, so a seed
// gives the same corners on every platform.
#pragma once
#include <vector>

#include "base/prng.h"
#include "scene/line_scene.h"  // Point2

namespace qt::scene {

// Pinhole camera, x right, y down, z forward; pixel centres at integer coordinates.
struct PinholeCamera {
    double f, cx, cy;  // focal length and principal point, px
    int w, h;          // frame, px
};

// Principal point at the frame centre ((w − 1) / 2, (h − 1) / 2); focal_px 0 = the width.
PinholeCamera centred_camera(int w, int h, double focal_px);

// The pose of a board of height 1 and width `aspect`:
//  - rotation_deg: in-plane turn about the board normal, applied first; positive turns
//    clockwise as seen (y down): at tilt 0 the top side points along (cos r, sin r);
//  - tilt_deg: angle between the board normal and the optical axis, about an axis lying in the
//    board plane at tilt_axis_deg from the display's x axis (before the rotation);
//  - scale: max(bbox width / frame width, bbox height / frame height) of the projected corners.
struct BoardPose {
    double tilt_deg = 0, rotation_deg = 0, tilt_axis_deg = 0, scale = 0;
};

// Corners (top-left, bottom-left, bottom-right, top-right of the display: anti-clockwise as
// seen) of the board at `pose` whose bounding-box centre lies at (tx, ty) px (to about 0.01 px:
// the viewing ray is corrected 12 times).
void project_board_at(const PinholeCamera& cam, double aspect, const BoardPose& pose, double tx,
                      double ty, Point2 out[4]);

// Whether every corner lies at least `margin` px inside the outermost pixel centres, and the
// quadrangle is convex and anti-clockwise as seen.
bool board_fits(const PinholeCamera& cam, const Point2 corners[4], double margin);

// Ranges drawn uniformly, degrees and the scale as in BoardPose.
struct PoseRanges {
    double tilt_deg_min, tilt_deg_max, rotation_deg_min, rotation_deg_max, scale_min, scale_max;
};

// Draws tilt, tilt axis, rotation and scale, then a position whose corners fit 4 px inside
// the frame; writes the corners. Throws std::runtime_error if 500 positions do not fit.
BoardPose place_board(const PinholeCamera& cam, double aspect, const PoseRanges& ranges, Pcg32& rng,
                      Point2 corners[4]);

// How much of a side an arm may hide: at most max_fraction of the side, and at least
// max(end_px, end_fraction × side) px of the side visible at each end.
struct ArmLimits {
    double max_fraction = 0.5;
    double end_px = 10;
    double end_fraction = 0;
};

struct Occluder {
    int side = -1;  // corners[side] -> corners[side + 1 mod 4]; -1: none placed
    double from = 0,
           to = 0;  // the covered part of that side, fractions of its length from corners[side]
    std::vector<Point2> outline;  // polygon to paint, px
    int level = 0;                // its grey level
};

// An arm from beyond the frame edge over part of one side (>= 30 px long) of an anti-clockwise
// board: a band with a rounded tip whose outer part lies wholly outside the board and whose tip
// stays >= 4 px inside the other sides; grey 20..board_level − 60. side −1 when none fits.
Occluder arm_occluder(const Point2 corners[4], int board_level, const ArmLimits& limits, int w,
                      int h, Pcg32& rng);

// The parts of an arm that crosses a side at a -> b (the covered part, px) along the outward
// unit direction (dx, dy), which makes the angle φ with the side's outward normal:
// arm_tip: the rounded tip `depth` px inside the side (a half ellipse from a's side to b's,
// 9 points); arm_outline: the tip joined to two points beyond a w × h frame.
std::vector<Point2> arm_tip(Point2 a, Point2 b, double dx, double dy, double cos_phi, double width,
                            double depth);
std::vector<Point2> arm_outline(Point2 a, Point2 b, const std::vector<Point2>& tip, double dx,
                                double dy, int w, int h);

// Signed distance of q from the side a -> b of an anti-clockwise-as-seen polygon, px;
// positive inside.
double inside_distance(Point2 a, Point2 b, Point2 q);
double point_distance(Point2 a, Point2 b);  // px

}  // namespace qt::scene
